#include "NumberOption.hpp"

#include "physim/framework/RunOptions.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace physim {

double parseNumberOption(const std::string& flag, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
        throw UsageError(flag + " expects a number, got '" + text + "'");
    return v;
}

int parseCountOption(const std::string& flag, const std::string& text, int lo, int hi) {
    const double v = parseNumberOption(flag, text);
    if (!(v >= lo && v <= hi) || v != std::floor(v))
        throw UsageError(flag + " must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "], got " + text);
    return static_cast<int>(v);
}

}  // namespace physim
