// SPDX-License-Identifier: MIT
// Read time of STEP/IGES files with and without the process boundary, in one
// run: each file is read in this process (the reader linked in, OpenCASCADE
// loaded once, as the library did before issue 31) and through
// read_step_iges (a worker of the reader's server), alternately, `--repeat N`
// times each; the minimum wall and CPU time of each is kept (the CPU time of
// a boundary read is this process's, the server's and the worker's:
// ServerClock). Both must give the same model, byte for byte in the exchange
// form, or the same error line. Prints a Markdown table
// (docs/results/step_iges_boundary.md). `--side in-process|boundary` reads
// one way only, for a profiler (the table's other columns then mean nothing).
#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges.h>
#include <seamless/model/step_iges/read_in_process.h>

#include <linux/perf_event.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace seamless;

// CPU seconds (user + system) of this process.
double own_cpu() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The reader's server: this process's child seamless-step-iges, or -1.
pid_t server_pid() {
    for (const auto& e : std::filesystem::directory_iterator("/proc")) {
        std::ifstream in(e.path() / "stat");
        std::string line;
        if (!std::getline(in, line) || line.find("(seamless-step-i") == std::string::npos) continue;
        std::istringstream fields(line.substr(line.rfind(')') + 2));
        std::string state;
        pid_t parent = 0;
        fields >> state >> parent;
        if (parent == getpid()) return static_cast<pid_t>(std::stol(e.path().filename().string()));
    }
    return -1;
}

// CPU seconds of the reader's server and of every worker it forks after
// start(): a task-clock perf counter on the server that its children inherit
// and hand back when they end (in ns, their exits' teardown included). Where
// perf events are refused, the workers the server has reaped: its cutime +
// cstime (/proc/PID/stat, 10-ms ticks).
class ServerClock {
  public:
    void start() {
        pid_ = server_pid();
        perf_event_attr a{};
        a.size = sizeof a;
        a.type = PERF_TYPE_SOFTWARE;
        a.config = PERF_COUNT_SW_TASK_CLOCK;
        a.inherit = 1;
        if (pid_ > 0) fd_ = static_cast<int>(syscall(SYS_perf_event_open, &a, pid_, -1, -1, 0));
    }
    bool precise() const { return fd_ >= 0; }
    double seconds() const {
        std::uint64_t ns = 0;
        if (fd_ >= 0 && read(fd_, &ns, sizeof ns) == sizeof ns) return 1e-9 * double(ns);
        std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
        std::string line;
        if (pid_ <= 0 || !std::getline(in, line)) return 0;
        std::istringstream fields(line.substr(line.rfind(')') + 2));
        std::string f[15];
        for (std::string& x : f) fields >> x;
        return static_cast<double>(std::stoll(f[13]) + std::stoll(f[14])) /
               static_cast<double>(sysconf(_SC_CLK_TCK)); // fields 16, 17
    }

  private:
    pid_t pid_ = -1;
    int fd_ = -1;
};

ServerClock server_clock;

struct Timing {
    double wall = 0, cpu = 0;
};

// The times of one read and what it gave: the model's exchange bytes with
// its warnings, or the error line.
Timing timed(const std::function<Model()>& read, std::string& result) {
    const double c0 = own_cpu() + server_clock.seconds();
    const auto t0 = std::chrono::steady_clock::now();
    try {
        result = "model " + write_model_exchange(read());
    } catch (const InputError& e) {
        result = std::string("error ") + e.what();
    }
    Timing t;
    t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t.cpu = own_cpu() + server_clock.seconds() - c0;
    return t;
}

Timing min(Timing a, Timing b) {
    return {std::min(a.wall, b.wall), std::min(a.cpu, b.cpu)};
}

} // namespace

int main(int argc, char** argv) {
    int repeat = 3;
    std::string side; // empty: both
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
            repeat = std::atoi(argv[++i]);
        else if (std::strcmp(argv[i], "--side") == 0 && i + 1 < argc)
            side = argv[++i];
        else
            files.push_back(argv[i]);
    }
    if (files.empty() || repeat < 1) {
        std::fprintf(
            stderr,
            "usage: step_iges_boundary [--repeat N] [--side in-process|boundary] FILE...\n");
        return 2;
    }
    const ModelLoadOptions options;
    std::string warm;
    // OpenCASCADE loaded here, the reader's server started: both once per process.
    timed([&] { return step_iges::read_step_iges_in_process(files[0], options); }, warm);
    timed([&] { return read_step_iges(files[0], options); }, warm);
    server_clock.start();
    std::fprintf(stderr, "workers' CPU time: %s\n",
                 server_clock.precise() ? "task-clock perf counter (ns)" : "10-ms ticks");
    std::printf(
        "| file | in process: wall, CPU (s) | boundary: wall, CPU (s) | cost: wall, CPU (ms) "
        "| within budget: wall, CPU | same result |\n| --- | ---: | ---: | ---: | --- | --- |\n");
    int over = 0, differ = 0;
    Timing sum_here, sum_there;
    for (const std::string& f : files) {
        Timing here{1e300, 1e300}, there{1e300, 1e300};
        std::string a, b;
        for (int k = 0; k < repeat; ++k) {
            if (side != "boundary")
                here =
                    min(here,
                        timed([&] { return step_iges::read_step_iges_in_process(f, options); }, a));
            if (side != "in-process")
                there = min(there, timed([&] { return read_step_iges(f, options); }, b));
        }
        sum_here = {sum_here.wall + here.wall, sum_here.cpu + here.cpu};
        sum_there = {sum_there.wall + there.wall, sum_there.cpu + there.cpu};
        // The budget: 5 % or 20 ms, whichever is larger.
        const auto within = [](double a, double b) { return b - a <= std::max(0.05 * a, 0.020); };
        const bool wall_ok = within(here.wall, there.wall), cpu_ok = within(here.cpu, there.cpu);
        over += !cpu_ok;
        differ += a != b;
        const std::string name = f.substr(f.find_last_of('/') + 1);
        std::printf("| %s | %.3f, %.2f | %.3f, %.2f | %.0f, %.0f | %s, %s | %s |\n", name.c_str(),
                    here.wall, here.cpu, there.wall, there.cpu, 1e3 * (there.wall - here.wall),
                    1e3 * (there.cpu - here.cpu), wall_ok ? "yes" : "**no**",
                    cpu_ok ? "yes" : "**no**",
                    a == b ? (a.rfind("error", 0) == 0 ? "yes (error)" : "yes") : "**no**");
        std::fflush(stdout);
    }
    std::printf(
        "| **all %zu** | %.2f, %.2f | %.2f, %.2f | %+.1f %%, %+.1f %% | %d over in CPU | %d differ "
        "|\n",
        files.size(), sum_here.wall, sum_here.cpu, sum_there.wall, sum_there.cpu,
        100 * (sum_there.wall / sum_here.wall - 1), 100 * (sum_there.cpu / sum_here.cpu - 1), over,
        differ);
    return differ ? 1 : 0;
}
