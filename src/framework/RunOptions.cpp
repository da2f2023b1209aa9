#include "physim/framework/RunOptions.hpp"

#include "AccuracyOptions.hpp"
#include "NumberOption.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

namespace physim {
namespace {

// A bound as the messages show it: "1", "10000", "1e+07".
std::string bound(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// ID:QUANTITY, the id a non-negative integer and the quantity one of RecordSpec::quantities().
RecordSpec parseRecord(const std::string& text) {
    const auto colon = text.find(':');
    const std::string id = text.substr(0, colon);
    if (colon == std::string::npos || id.empty() || id.find_first_not_of("0123456789") != std::string::npos ||
        id.size() > 9)
        throw UsageError("--record expects ID:QUANTITY with ID an entity's id (a whole number), got '" + text + "'");
    RecordSpec spec{std::stoi(id), text.substr(colon + 1)};
    const auto& known = RecordSpec::quantities();
    if (std::find(known.begin(), known.end(), spec.quantity) == known.end()) {
        std::string list;
        for (const std::string& q : known) list += (list.empty() ? "" : ", ") + q;
        throw UsageError("--record " + text + ": unknown quantity '" + spec.quantity + "' (one of " + list + ")");
    }
    return spec;
}

}  // namespace

const std::vector<std::string>& RecordSpec::quantities() {
    static const std::vector<std::string> names{"x",     "y",
                                                "angle", "vx",
                                                "vy",    "speed",
                                                "angular_velocity", "kinetic_energy",
                                                "contact_force",    "joint_force"};
    return names;
}

const char* RecordSpec::unit(const std::string& q) {
    if (q == "x" || q == "y") return "m";
    if (q == "angle") return "rad";
    if (q == "vx" || q == "vy" || q == "speed") return "m/s";
    if (q == "angular_velocity") return "rad/s";
    if (q == "kinetic_energy") return "J";
    if (q == "contact_force" || q == "joint_force") return "N";
    return "";
}

RunOptions parseRunOptions(const std::vector<std::string>& args) {
    RunOptions o;
    o.arguments = args;
    for (std::size_t i = 0; i < args.size(); ++i) {
        // --name=value is --name value.
        const std::size_t equals = args[i].rfind("--", 0) == 0 ? args[i].find('=') : std::string::npos;
        const std::string a = args[i].substr(0, equals);
        std::optional<std::string> inlineValue;
        if (equals != std::string::npos) inlineValue = args[i].substr(equals + 1);
        auto value = [&]() -> const std::string& {
            if (inlineValue) return *inlineValue;
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        const auto flag = [&] {  // an option without a value
            if (inlineValue) throw UsageError(a + " takes no value, got '" + args[i] + "'");
        };
        if (a == "--help" || a == "-h") {
            flag();
            o.help = true;
        } else if (a == "--headless") {
            flag();
            o.headless = true;
        } else if (a == "--quiet") {
            flag();
            o.quiet = true;
        } else if (a == "--seconds") {
            const std::string& text = value();
            const double s = parseNumberOption(a, text);
            if (!(s >= 0.0 && s <= RunOptions::maxSeconds))
                throw UsageError("--seconds must be in [0, " + bound(RunOptions::maxSeconds) + "] s, got " + text);
            o.seconds = s;
        } else if (a == "--hz") {
            const std::string& text = value();
            const double hz = parseNumberOption(a, text);
            if (!(hz >= RunOptions::minHz && hz <= RunOptions::maxHz))
                throw UsageError("--hz must be in [" + bound(RunOptions::minHz) + ", " + bound(RunOptions::maxHz) +
                                 "] Hz, got " + text);
            o.hz = hz;
        } else if (a == "--out") {
            const std::string& text = value();
            if (text.empty()) throw UsageError("--out needs a directory, got ''");
            o.outDir = text;
        } else if (a == "--screenshot") {
            const std::string& text = value();
            if (text.empty()) throw UsageError("--screenshot needs a file name, got ''");
            o.screenshot = text;
        } else if (a == "--param") {
            const std::string& text = value();
            const auto eq = text.find('=');
            if (eq == std::string::npos || eq == 0)
                throw UsageError("--param expects NAME=VALUE, got '" + text + "'");
            const double v = parseNumberOption("--param " + text.substr(0, eq), text.substr(eq + 1));
            o.parameters.emplace_back(text.substr(0, eq), v);
        } else if (a == "--record") {
            o.records.push_back(parseRecord(value()));
        } else if (a == "--replay") {
            const std::string& text = value();
            if (text.empty()) throw UsageError("--replay needs a run.json file, got ''");
            o.replay = text;
        } else if (a == "--snapshot-every") {
            o.snapshotEvery = parseCountOption(a, value(), 1, 1000000000);
        } else if (a == "--from") {
            const std::string& text = value();
            if (text.empty()) throw UsageError("--from needs a snapshot file, got ''");
            o.from = text;
        } else if (a == "--max-steps-per-frame") {
            o.maxStepsPerFrame = parseCountOption(a, value(), 1, 1000);
        } else if (a == "--size") {
            const std::string& text = value();
            const auto x = text.find('x');
            if (x == std::string::npos) throw UsageError("--size expects WIDTHxHEIGHT, got '" + text + "'");
            o.width = parseCountOption(a, text.substr(0, x), 64, 16384);
            o.height = parseCountOption(a, text.substr(x + 1), 64, 16384);
        } else if (!parseAccuracyOption(a, value, o)) {
            throw UsageError("unknown argument '" + args[i] + "' (see --help)");
        }
    }
    checkAccuracyOptions(o);
    if (!o.records.empty() && !o.outDir && !o.help) throw UsageError("--record writes into --out DIR: give --out too");
    if (o.replay) {  // the run comes from the file: only --quiet may join it
        for (const std::string& arg : args) {
            const std::string name = arg.substr(0, arg.find('='));
            if (name.rfind("--", 0) == 0 && name != "--replay" && name != "--quiet")
                throw UsageError("--replay runs what the file records: " + name + " cannot join it");
        }
    }
    if (o.snapshotEvery && !o.headless)
        throw UsageError("--snapshot-every is for --headless runs (a window keeps its own timeline)");
    if (o.snapshotEvery && !o.outDir) throw UsageError("--snapshot-every writes into --out DIR: give --out");
    if (o.headless && o.screenshot)
        throw UsageError("--screenshot needs a window: a --headless run draws nothing to save");
    return o;
}

std::string usage(std::string_view program, std::string_view title) {
    std::ostringstream os;
    os << title << "\n\n"
       << "usage: " << program << " [options]\n\n"
       << "  --headless               run without a window (no display needed)\n"
       << "  --seconds S              simulated seconds to run (headless default "
       << RunOptions::defaultHeadlessSeconds << "; in a window: until closed)\n"
       << "  --out DIR                write summary.json (final state, SI units), run.json (how to replay the run)\n"
       << "                           and the graphs (graph_<i>.csv, graphs.png, graphs.root) to DIR at the end;\n"
       << "                           DIR is created and checked before the run\n"
       << "  --quiet                  no progress on stderr for long headless runs, no closing line\n"
       << "  --hz H                   physics rate in Hz, " << bound(RunOptions::minHz) << " to "
       << bound(RunOptions::maxHz) << " (default: the simulation's, 40 as in\n"
       << "                           the paper)\n"
       << "  --param NAME=VALUE       set one of the simulation's parameters (listed below, if it has any)\n"
       << "  --screenshot FILE.png    window: save the last frame drawn when the run ends\n"
       << "  --record ID:QUANTITY     with --out, record the quantity of the entity with that id (summary.json's\n"
       << "                           ids) after every step into records.csv and graphs.root; repeatable. QUANTITY:\n"
       << "                           x, y, angle, vx, vy, speed, angular_velocity, kinetic_energy (SI units)\n"
       << "  --replay RUN.json        run again the run that RUN.json records (written by --out) and say whether\n"
       << "                           it ends in the same state (exit 0) or not (exit 1)\n"
       << "  --snapshot-every N       headless, with --out: every N physics steps, write a snapshot of the run to\n"
       << "                           DIR/snapshots/step-<steps>.psnap (<steps>: the world's step count, 9 digits)\n"
       << "  --from FILE.psnap        start from a snapshot file (--snapshot-every's, or an interrupted run's) once\n"
       << "                           the scene is built: the same scene, parameters and --hz (the file's world\n"
       << "                           keeps its accuracy settings); --seconds then counts from the snapshot's time\n"
       << "  --max-steps-per-frame N  at most N physics steps per window frame, catching up as far as N allows\n"
          "                           (default: as many as keep 20 frames per second, at least 1; slow motion beyond)\n"
       << "  --size WxH               window size in pixels (default 1280x720)\n"
       << accuracyUsage()
       << "  --help                   this text\n"
       << "  --name=value is the same as --name value.\n\n"
       << "in a window: " << "Space restart, P pause, O one step, Left / Right back / forward 1 s (pauses; the\n"
       << "  run is recorded as it goes), Home back to the start, B start or end a branch, [ ] slower / faster,\n"
       << "  F fit the view, Tab statistics, 1-8 debug drawing (contacts, boxes, velocities, joints, centres,\n"
       << "  sleep, sensors, rays), left drag moves a body, right drag pans, the wheel zooms about the cursor,\n"
       << "  Esc quits; the simulation may add its own keys. Instruments: W stopwatch in simulated seconds (start,\n"
       << "  stop, start anew); M + left drag tape measure (m); A + left drag along one arm, then a click, protractor\n"
       << "  (degrees); a plain click clears them; L trails (the last 5 s of path of up to 64 bodies, the picked one\n"
       << "  and those that moved faster than 0.1 m/s; a scrub or restart clears them); V arrows from each body's\n"
       << "  centre of mass: velocity, weight and contact force, at the scales the bar states.\n"
       << "Ctrl-C (SIGINT) or SIGTERM stops the run at the end of its step and writes --out, with a snapshot that\n"
       << "  --from resumes; a second one stops it at once.\n"
       << "exit codes: 0 success, 1 error while running, 2 bad arguments, 130 stopped by SIGINT, 143 by SIGTERM.\n";
    return os.str();
}

}  // namespace physim
