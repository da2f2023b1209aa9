#include "RunRecord.hpp"

#include "physim/framework/RunOptions.hpp"

#include <nlohmann/json.hpp>

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <sstream>

#ifndef PHYSIM_COMMIT
#define PHYSIM_COMMIT "unknown"
#endif
#ifndef PHYSIM_COMPILER
#define PHYSIM_COMPILER "unknown"
#endif
#ifndef PHYSIM_BUILD_TYPE
#define PHYSIM_BUILD_TYPE "unknown"
#endif

namespace physim {
namespace {

constexpr const char* kFormat = "physim-run";
constexpr int kVersion = 1;

[[noreturn]] void bad(const std::string& path, const std::string& problem) {
    throw UsageError("--replay " + path + ": " + problem);
}

const nlohmann::json& field(const nlohmann::json& j, const std::string& path, const char* name,
                            nlohmann::json::value_t type, const char* typeName) {
    if (!j.contains(name)) bad(path, std::string("no \"") + name + "\" field");
    const nlohmann::json& v = j.at(name);
    const bool numberWanted = type == nlohmann::json::value_t::number_float;
    if (numberWanted ? !v.is_number() : v.type() != type)
        bad(path, std::string("\"") + name + "\" must be " + typeName + ", got " + v.dump());
    return v;
}

}  // namespace

std::string hashText(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016" PRIx64, hash);
    return text;
}

std::string buildDescription() {
    return std::string("commit ") + PHYSIM_COMMIT + ", " + PHYSIM_COMPILER + ", " + PHYSIM_BUILD_TYPE;
}

std::string runRecordJson(const std::string& program, const std::vector<std::string>& arguments,
                          const Simulation& sim) {
    const World& world = sim.world();
    const WorldSettings& s = world.settings();
    nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
    for (const Parameter& p : sim.parameters.all()) parameters[p.name] = p.value;
    const nlohmann::ordered_json record{
        {"format", kFormat},
        {"version", kVersion},
        {"program", program},
        {"arguments", arguments},
        {"parameters", parameters},
        {"physics_rate_hz", sim.physicsRate()},
        {"time_step_s", sim.fixedTimeStep()},
        {"substeps", s.substeps},
        {"velocity_iterations", s.velocityIterations},
        {"threads", s.threads},
        {"seed", nullptr},
        {"steps", world.stepCount()},
        {"time_s", sim.time},
        {"build", {{"commit", PHYSIM_COMMIT}, {"compiler", PHYSIM_COMPILER}, {"build_type", PHYSIM_BUILD_TYPE}}},
        {"final_state_hash", hashText(world.stateHash())},
    };
    return record.dump(2) + "\n";
}

RecordedRun readRunRecord(const std::string& path, const std::string& program) {
    std::ifstream in(path);
    if (!in) bad(path, "cannot read the file");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        bad(path, std::string("not valid JSON (") + e.what() + ")");
    }
    if (!j.is_object()) bad(path, "not a JSON object");
    using T = nlohmann::json::value_t;
    if (field(j, path, "format", T::string, "a string").get<std::string>() != kFormat)
        bad(path, "not a physim run record (\"format\" is " + j["format"].dump() + ")");
    const nlohmann::json& version = field(j, path, "version", T::number_unsigned, "a whole number");
    if (version.get<int>() != kVersion)
        bad(path, "version " + version.dump() + "; this program reads version " + std::to_string(kVersion));
    RecordedRun r;
    r.program = field(j, path, "program", T::string, "a string").get<std::string>();
    if (r.program != program) bad(path, "a run of " + r.program + ", not of " + program);
    for (const nlohmann::json& a : field(j, path, "arguments", T::array, "a list of strings")) {
        if (!a.is_string()) bad(path, "\"arguments\" must hold strings, got " + a.dump());
        r.arguments.push_back(a.get<std::string>());
    }
    r.steps = field(j, path, "steps", T::number_unsigned, "a whole number").get<std::uint64_t>();
    r.timeStep = field(j, path, "time_step_s", T::number_float, "a number").get<double>();
    if (!(r.timeStep > 0.0 && r.timeStep <= 1.0))
        bad(path, "\"time_step_s\" must be in (0, 1] s, got " + j["time_step_s"].dump());
    const std::string hash = field(j, path, "final_state_hash", T::string, "a string").get<std::string>();
    if (hash.size() != 16 || hash.find_first_not_of("0123456789abcdef") != std::string::npos)
        bad(path, "\"final_state_hash\" must be 16 lowercase hex digits, got \"" + hash + "\"");
    r.stateHash = std::stoull(hash, nullptr, 16);
    if (j.contains("build") && j["build"].is_object()) {
        const nlohmann::json& b = j["build"];
        std::ostringstream os;
        os << "commit " << b.value("commit", "unknown") << ", " << b.value("compiler", "unknown") << ", "
           << b.value("build_type", "unknown");
        r.build = os.str();
    }
    return r;
}

}  // namespace physim
