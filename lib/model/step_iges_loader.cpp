// SPDX-License-Identifier: MIT
// STEP/IGES behind a process boundary: OpenCASCADE's readers were not written
// for hostile files (a damaged file can make them dereference null entities or
// index past arrays; docs/fuzzing.md), so they run in a process of their own,
// the executable seamless-step-iges beside libseamless (step_iges_process.h).
// A crash, a time-out or a memory blow-up there ends as one InputError naming
// the file, and the calling program (CLI, Python module, batch) never maps
// OpenCASCADE's libraries. posix_spawn, not fork: the caller may have threads.
#include <seamless/model/step_iges.h>

#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges_process.h>

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>
#include <thread>

extern char** environ;

namespace seamless {
namespace {

namespace proc = step_iges_process;
using Clock = std::chrono::steady_clock;

// The reader's path: beside the file holding this code (libseamless.so, or
// the program itself where the library is linked in, as in the fuzz build).
std::filesystem::path reader_path() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&reader_path), &info) && info.dli_fname)
        return std::filesystem::path(info.dli_fname).parent_path() / proc::kExecutable;
    return proc::kExecutable;
}

std::string errno_text(int e) {
    return std::strerror(e);
}

// A running reader: its pid and the read end of its answer pipe. Killed and
// reaped unless finished (exceptions leave no process behind).
class Reader {
  public:
    Reader(const std::filesystem::path& exe, const std::string& file,
           const ModelLoadOptions& options);
    ~Reader() {
        if (fd_ >= 0) close(fd_);
        if (pid_ > 0) {
            kill(pid_, SIGKILL);
            int status;
            reap(0, status);
        }
    }
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;

    // The answer, or false when the deadline passed first.
    bool read_answer(Clock::time_point deadline, std::string& answer);
    // The exit status (waitpid's), or false when the deadline passed first.
    bool finish(Clock::time_point deadline, int& status);

  private:
    // True once the reader is gone: its status, or -1 when the caller reaped
    // it (a SIGCHLD handler, or SIGCHLD ignored).
    bool reap(int flags, int& status) {
        status = -1;
        pid_t r;
        while ((r = waitpid(pid_, &status, flags)) < 0 && errno == EINTR) {
        }
        if (r == 0) return false;
        if (r < 0) status = -1;
        pid_ = -1;
        return true;
    }
    pid_t pid_ = -1;
    int fd_ = -1;
    std::string file_;
};

Reader::Reader(const std::filesystem::path& exe, const std::string& file,
               const ModelLoadOptions& options)
    : file_(file) {
    int fds[2];
    // Close-on-exec: another thread's reader must not hold this write end.
    if (pipe2(fds, O_CLOEXEC) != 0)
        throw InputError(file, "",
                         "cannot start the STEP/IGES reader (pipe: " + errno_text(errno) + ")");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], proc::kAnswerFd);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    // OpenCASCADE may print on stdout, which is the caller's output.
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    // Default dispositions and no blocked signal: a caller that ignores
    // SIGPIPE (Python does) must not pass that on.
    sigset_t all, none;
    sigfillset(&all);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attr, &all);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    const std::string exe_name = exe.string(), args = proc::encode_options(options);
    char* argv[] = {const_cast<char*>(exe_name.c_str()), const_cast<char*>(args.c_str()),
                    const_cast<char*>(file.c_str()), nullptr};
    const int rc = posix_spawn(&pid_, exe_name.c_str(), &actions, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close(fds[1]);
    fd_ = fds[0];
    if (rc != 0) {
        pid_ = -1;
        throw InputError(file, "",
                         "STEP/IGES support is not installed (cannot run " + exe_name + ": " +
                             errno_text(rc) + ")");
    }
}

int millis_until(Clock::time_point deadline) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    return static_cast<int>(std::clamp<long long>(left.count() + 1, 0, 1000));
}

bool Reader::read_answer(Clock::time_point deadline, std::string& answer) {
    char buf[1 << 16];
    for (;;) {
        if (Clock::now() >= deadline) return false;
        pollfd p{fd_, POLLIN, 0};
        const int r = poll(&p, 1, millis_until(deadline));
        if (r < 0 && errno != EINTR)
            throw InputError(
                file_, "", "cannot read the STEP/IGES reader's answer (" + errno_text(errno) + ")");
        if (r <= 0) continue;
        const ssize_t n = read(fd_, buf, sizeof buf);
        if (n == 0) return true;
        if (n > 0)
            answer.append(buf, static_cast<size_t>(n));
        else if (errno != EINTR && errno != EAGAIN)
            throw InputError(
                file_, "", "cannot read the STEP/IGES reader's answer (" + errno_text(errno) + ")");
    }
}

bool Reader::finish(Clock::time_point deadline, int& status) {
    // The answer is complete: the reader is exiting (it skips its destructors).
    for (;;) {
        if (reap(WNOHANG, status)) return true;
        if (Clock::now() >= deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

std::string signal_text(int sig) {
    const char* name = sigabbrev_np(sig);
    return "signal " + std::to_string(sig) + (name ? std::string(", SIG") + name : "");
}

std::string limit_text(double x, const char* unit) {
    if (!(x > 0)) return "none";
    std::ostringstream s;
    s << x << unit;
    return s.str();
}

// The reader's model, or its InputError, from a complete answer.
Model take_answer(const std::string& answer, const std::string& file,
                  const ModelLoadOptions& options) {
    if (!answer.empty() && answer[0] == 'M') {
        try {
            return read_model_exchange(std::string_view(answer).substr(1), file, options.limits);
        } catch (const InputError& e) {
            throw InputError(file, "",
                             "the STEP/IGES reader's answer is malformed (" + e.field() + ": " +
                                 e.message() + ")");
        }
    }
    std::string f, field, message;
    if (proc::decode_error(answer, f, field, message)) throw InputError(f, field, message);
    throw InputError(file, "",
                     "the STEP/IGES reader's answer is malformed (" +
                         std::to_string(answer.size()) + " bytes, neither a model nor an error)");
}

} // namespace

bool is_step_iges_extension(const std::string& ext) {
    return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

Model read_step_iges(const std::filesystem::path& path, const ModelLoadOptions& options) {
    const std::string file = path.string();
    const double limit = options.reader_time_limit;
    const auto deadline = limit > 0 && limit < 1e9
                              ? Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                   std::chrono::duration<double>(limit))
                              : Clock::time_point::max();
    Reader reader(reader_path(), file, options);
    std::string answer;
    int status = 0;
    if (!reader.read_answer(deadline, answer) || !reader.finish(deadline, status)) {
        throw InputError(file, "",
                         "OpenCASCADE took longer than the time limit of " +
                             limit_text(limit, " s") +
                             " reading it (ModelLoadOptions::reader_time_limit)");
    }
    if (status == -1 && !answer.empty())
        return take_answer(answer, file, options); // reaped elsewhere
    if (WIFSIGNALED(status))
        throw InputError(file, "",
                         "OpenCASCADE crashed reading it (" + signal_text(WTERMSIG(status)) + ")");
    if (WIFEXITED(status) && WEXITSTATUS(status) == proc::kOutOfMemory)
        throw InputError(
            file, "",
            "OpenCASCADE ran out of memory reading it (the reader's limit is " +
                limit_text(std::ldexp(double(options.reader_memory_limit), -20), " MiB") +
                ", ModelLoadOptions::reader_memory_limit)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw InputError(file, "",
                         "the STEP/IGES reader failed on it (exit status " +
                             std::to_string(WEXITSTATUS(status)) + ")");
    return take_answer(answer, file, options);
}

} // namespace seamless
