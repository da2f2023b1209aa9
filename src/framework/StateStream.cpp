// StateWriter and StateReader (StateStream.hpp): numbers as their bytes, little-endian as the snapshot files.

#include "physim/framework/StateStream.hpp"

#include <cstring>
#include <stdexcept>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "snapshot files are little-endian, as this build's numbers");

namespace physim {

void StateWriter::putDouble(double v) { bytes_.append(reinterpret_cast<const char*>(&v), sizeof v); }
void StateWriter::putInt(std::int64_t v) { bytes_.append(reinterpret_cast<const char*>(&v), sizeof v); }
void StateWriter::putBool(bool v) { bytes_.push_back(v ? '\1' : '\0'); }
void StateWriter::putDoubles(const std::vector<double>& v) {
    putInt(static_cast<std::int64_t>(v.size()));
    if (!v.empty()) bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

void StateReader::take(void* to, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    if (n > left())
        throw std::runtime_error("physim: snapshot file: the simulation's own state ends early (" +
                                 std::to_string(left()) + " bytes left, " + std::to_string(n) + " wanted)");
    std::memcpy(to, bytes_.data() + at_, n);
    at_ += n;
}

double StateReader::getDouble() {
    double v = 0.0;
    take(&v, sizeof v);
    return v;
}
std::int64_t StateReader::getInt() {
    std::int64_t v = 0;
    take(&v, sizeof v);
    return v;
}
bool StateReader::getBool() {
    unsigned char b = 0;
    take(&b, 1);
    return b != 0;
}
std::vector<double> StateReader::getDoubles() {
    const std::int64_t n = getInt();
    if (n < 0 || static_cast<std::uint64_t>(n) > left() / sizeof(double))
        throw std::runtime_error("physim: snapshot file: the simulation's own state holds " + std::to_string(n) +
                                 " numbers, more than its " + std::to_string(left()) + " bytes left");
    std::vector<double> v(static_cast<std::size_t>(n));
    take(v.data(), v.size() * sizeof(double));
    return v;
}

}  // namespace physim
