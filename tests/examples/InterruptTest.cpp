// Interrupting a headless run as a user would (Ctrl-C sends SIGINT; a service manager SIGTERM): the run stops at the
// end of its current step, writes what it recorded to --out, says so, and exits with 128 + the signal; a second
// signal ends it at once; the snapshot it writes (and names) resumes with --from. The program: gas, asked for 3000 s (minutes of work), so only the signal can end it early.

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The bar: stopped and written within 2 s. Sanitized builds run the program several times slower.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kStopSeconds = 8.0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kStopSeconds = 8.0;
#else
constexpr double kStopSeconds = 2.0;
#endif
#else
constexpr double kStopSeconds = 2.0;
#endif

struct Child {
    pid_t pid = -1;
    fs::path log;
};

Child startGas(const fs::path& out) {
    Child c;
    c.log = out.string() + ".log";
    const std::string program = PHYSIM_GAS;
    std::vector<std::string> args = {program, "--headless", "--seconds", "3000", "--out", out.string()};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, c.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    EXPECT_EQ(posix_spawn(&c.pid, program.c_str(), &files, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&files);
    return c;
}

// The child's exit status as a shell reports it (128 + the signal for one that a signal ended: a second Ctrl-C that
// arrives while the program is already exiting ends it by the default action), or -1 if it is still running after
// `limit` (then it is killed).
int waitFor(const Child& c, std::chrono::duration<double> limit, double& took) {
    const auto start = Clock::now();
    while (Clock::now() - start < limit) {
        int status = 0;
        if (waitpid(c.pid, &status, WNOHANG) == c.pid) {
            took = std::chrono::duration<double>(Clock::now() - start).count();
            if (WIFEXITED(status)) return WEXITSTATUS(status);
            return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -2;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(c.pid, SIGKILL);
    waitpid(c.pid, nullptr, 0);
    return -1;
}

std::string readAll(const fs::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Waits until the run shows progress (its loop runs, its handlers are in place) and at least `atLeast` has passed
// since it started: a loaded machine (sanitizers, parallel tests) may take seconds to load ROOT and start.
void waitUntilRunning(const Child& c, std::chrono::duration<double> atLeast) {
    const auto start = Clock::now();
    while (readAll(c.log).find("physim:") == std::string::npos && Clock::now() - start < std::chrono::seconds(120))
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(atLeast));
}

void expectStopsAndWrites(int signal, int status, const std::string& name) {
    const fs::path out = fs::temp_directory_path() / ("physim_interrupt_" + name);
    fs::remove_all(out);
    const Child c = startGas(out);
    waitUntilRunning(c, std::chrono::seconds(3));
    ASSERT_EQ(kill(c.pid, signal), 0);
    double took = 0.0;
    const int code = waitFor(c, std::chrono::duration<double>(kStopSeconds), took);
    const std::string log = readAll(c.log);
    EXPECT_EQ(code, status) << log;
    EXPECT_LT(took, kStopSeconds);
    EXPECT_NE(log.find("stopped by " + name), std::string::npos) << log;
    // What was recorded so far: the summary at the time it stopped, and the graphs' CSVs.
    std::ifstream summary(out / "summary.json");
    ASSERT_TRUE(summary) << log;
    const nlohmann::json s = nlohmann::json::parse(summary);
    EXPECT_GT(s["time"].get<double>(), 0.0);
    EXPECT_LT(s["time"].get<double>(), 3000.0);
    EXPECT_TRUE(fs::exists(out / "graph_0.csv"));
    // The snapshot the line names, which a run --from resumes at the time it stopped.
    const std::string named = "a snapshot that --from resumes, ";
    const std::size_t at = log.find(named);
    ASSERT_NE(at, std::string::npos) << log;
    const std::string snapshot = log.substr(at + named.size(), log.find(';', at) - at - named.size());
    EXPECT_TRUE(fs::exists(snapshot)) << log;
    const fs::path resumed = out / "resumed";
    const std::string command = std::string(PHYSIM_GAS) + " --headless --quiet --seconds 0.25 --from " + snapshot +
                                " --out " + resumed.string() + " > /dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream after(resumed / "summary.json");
    ASSERT_TRUE(after) << command;
    EXPECT_NEAR(nlohmann::json::parse(after)["time"].get<double>(), s["time"].get<double>() + 0.25, 1e-9);
    fs::remove_all(out);
    fs::remove(c.log);
}

TEST(Interrupt, SigintStopsAHeadlessRunThatWritesItsOutputs) { expectStopsAndWrites(SIGINT, 130, "SIGINT"); }

TEST(Interrupt, SigtermStopsAHeadlessRunThatWritesItsOutputs) { expectStopsAndWrites(SIGTERM, 143, "SIGTERM"); }

TEST(Interrupt, ASecondSigintEndsTheRunAtOnce) {
    const fs::path out = fs::temp_directory_path() / "physim_interrupt_twice";
    fs::remove_all(out);
    const Child c = startGas(out);
    waitUntilRunning(c, std::chrono::seconds(2));
    ASSERT_EQ(kill(c.pid, SIGINT), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // two signals at once may arrive as one
    ASSERT_EQ(kill(c.pid, SIGINT), 0);
    double took = 0.0;
    EXPECT_EQ(waitFor(c, std::chrono::duration<double>(kStopSeconds), took), 130) << readAll(c.log);
    fs::remove_all(out);
    fs::remove(c.log);
}

}  // namespace
