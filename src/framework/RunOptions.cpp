#include "physim/framework/RunOptions.hpp"

#include "AccuracyOptions.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace physim {
namespace {

double parseNumber(const std::string& flag, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE)
        throw UsageError(flag + " expects a number, got '" + text + "'");
    return v;
}

int parseInt(const std::string& flag, const std::string& text, int lo, int hi) {
    const double v = parseNumber(flag, text);
    if (!(v >= lo && v <= hi) || v != std::floor(v))
        throw UsageError(flag + " must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "], got " + text);
    return static_cast<int>(v);
}

}  // namespace

RunOptions parseRunOptions(const std::vector<std::string>& args) {
    RunOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--headless") {
            o.headless = true;
        } else if (a == "--quiet") {
            o.quiet = true;
        } else if (a == "--seconds") {
            const std::string& text = value();
            const double s = parseNumber(a, text);
            if (!(std::isfinite(s) && s >= 0.0)) throw UsageError("--seconds must be finite and >= 0, got " + text);
            o.seconds = s;
        } else if (a == "--hz") {
            const std::string& text = value();
            const double hz = parseNumber(a, text);
            if (!(std::isfinite(hz) && hz > 0.0 && hz <= 10000.0))
                throw UsageError("--hz must be in (0, 10000] Hz, got " + text);
            o.hz = hz;
        } else if (a == "--out") {
            const std::string& text = value();
            if (text.empty()) throw UsageError("--out needs a directory, got ''");
            o.outDir = text;
        } else if (a == "--screenshot") {
            const std::string& text = value();
            if (text.empty()) throw UsageError("--screenshot needs a file name, got ''");
            o.screenshot = text;
        } else if (a == "--max-steps-per-frame") {
            o.maxStepsPerFrame = parseInt(a, value(), 1, 1000);
        } else if (a == "--size") {
            const std::string& text = value();
            const auto x = text.find('x');
            if (x == std::string::npos) throw UsageError("--size expects WIDTHxHEIGHT, got '" + text + "'");
            o.width = parseInt(a, text.substr(0, x), 64, 16384);
            o.height = parseInt(a, text.substr(x + 1), 64, 16384);
        } else if (!parseAccuracyOption(a, value, o)) {
            throw UsageError("unknown argument '" + a + "' (see --help)");
        }
    }
    checkAccuracyOptions(o);
    return o;
}

std::string usage(std::string_view program, std::string_view title) {
    std::ostringstream os;
    os << title << "\n\n"
       << "usage: " << program << " [options]\n\n"
       << "  --headless               run without a window (no display needed)\n"
       << "  --seconds S              simulated seconds to run (headless default "
       << RunOptions::defaultHeadlessSeconds << "; in a window: until closed)\n"
       << "  --out DIR                write summary.json (final state, SI units) and the graphs\n"
       << "                           (graph_<i>.csv, graphs.png, graphs.root) to DIR at the end;\n"
       << "                           DIR is created and checked before the run\n"
       << "  --quiet                  no progress on stderr for long headless runs, no closing line\n"
       << "  --hz H                   physics rate in Hz (default: the simulation's, 40 as in the paper)\n"
       << "  --screenshot FILE.png    window: save the last frame drawn when the run ends\n"
       << "  --max-steps-per-frame N  cap on catch-up physics steps per window frame (default 8)\n"
       << "  --size WxH               window size in pixels (default 1280x720)\n"
       << accuracyUsage()
       << "  --help                   this text\n\n"
       << "keys (window): Space restart, P pause, Esc quit, mouse wheel zoom; the simulation may add its own.\n"
       << "exit codes: 0 success, 1 error while running, 2 bad arguments.\n";
    return os.str();
}

}  // namespace physim
