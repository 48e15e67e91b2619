// SPDX-License-Identifier: MIT
// STEP/IGES behind a process boundary: OpenCASCADE's readers were not written
// for hostile files (a damaged file can make them dereference null entities or
// index past arrays; docs/fuzzing.md), so they run in a process of their own,
// the executable seamless-step-iges beside libseamless (step_iges_process.h).
// A crash, a time-out or a memory blow-up there ends as one InputError naming
// the file, and the calling program (CLI, Python module, batch) never maps
// OpenCASCADE's libraries. The executable runs as a server that has loaded
// OpenCASCADE once and forks a worker per read (step_iges_server.h): a
// process start per read would cost 35 to 55 ms
// (docs/results/step_iges_boundary.md).
#include <seamless/model/step_iges.h>

#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges_process.h>
#include <seamless/model/step_iges_server.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace seamless {
namespace {

namespace proc = step_iges_process;
using Clock = std::chrono::steady_clock;

int millis_until(Clock::time_point deadline) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    return static_cast<int>(std::clamp<long long>(left.count() + 1, 0, 1000));
}

// A model answer's head: its tag and size (step_iges_process.h).
constexpr size_t kHead = 1 + sizeof(std::uint64_t);

// The room a model answer needs, from its head: the whole of it at once (a
// 26-MB model grown by doubling touched twice its size in fresh pages). The
// size is the worker's word, so at most 1 GiB is taken on it.
size_t reserved(const std::string& head) {
    if (head.size() < kHead || head[0] != proc::kModelAnswer) return 0;
    std::uint64_t size;
    std::memcpy(&size, head.data() + 1, sizeof size);
    return kHead + static_cast<size_t>(std::min<std::uint64_t>(size, std::uint64_t(1) << 30));
}

// One read by a worker of the reader's server: its pipes, and its pid once
// the server has said it. A worker not seen to end is killed (a time-out, or
// an exception here).
class Worker {
  public:
    Worker(const std::string& file, const ModelLoadOptions& options)
        : file_(file), pipes_(proc::request_read(file, options)) {}
    ~Worker() {
        // Timed out before the server said the pid (it was starting): wait for it.
        try {
            if (pid_ < 0 && !ended_ &&
                read_all(pipes_.status, sizeof pid_, Clock::now() + std::chrono::seconds(5),
                         status_bytes_) &&
                status_bytes_.size() >= sizeof pid_)
                std::memcpy(&pid_, status_bytes_.data(), sizeof pid_);
        } catch (const InputError&) { // a failed read: no pid to kill
        }
        if (pid_ > 0 && !ended_) kill(pid_, SIGKILL);
        close(pipes_.answer);
        close(pipes_.status);
    }
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    // The worker's answer and wait status; false when the deadline passed
    // first. A server that closed the status pipe early is a failure named.
    bool run(Clock::time_point deadline, std::string& answer, int& status) {
        if (!read_all(pipes_.status, sizeof pid_, deadline, status_bytes_)) return false;
        if (status_bytes_.size() < sizeof pid_)
            fail("the STEP/IGES reader's server did not start a worker for it");
        std::memcpy(&pid_, status_bytes_.data(), sizeof pid_);
        if (!read_all(pipes_.answer, kHead, deadline, answer)) return false;
        answer.reserve(reserved(answer));
        if (!read_all(pipes_.answer, SIZE_MAX, deadline, answer)) return false;
        if (!read_all(pipes_.status, sizeof pid_ + sizeof status, deadline, status_bytes_))
            return false;
        if (status_bytes_.size() < sizeof pid_ + sizeof status)
            fail("the STEP/IGES reader's server ended during the read");
        std::memcpy(&status, status_bytes_.data() + sizeof pid_, sizeof status);
        ended_ = true;
        return true;
    }

  private:
    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(file_, "", message);
    }

    // Reads fd into `out` until it holds `size` bytes or the end; false when
    // the deadline passed first. Straight into out's room (reserved for a
    // model: a pipe's worth a call); past it (the end, or more than the
    // worker said) through a small buffer.
    bool read_all(int fd, size_t size, Clock::time_point deadline, std::string& out) const {
        char spare[1 << 12];
        while (out.size() < size) {
            if (Clock::now() >= deadline) return false;
            pollfd p{fd, POLLIN, 0};
            const int r = poll(&p, 1, millis_until(deadline));
            if (r < 0 && errno != EINTR)
                fail("cannot read the STEP/IGES reader's answer (" +
                     std::string(std::strerror(errno)) + ")");
            if (r <= 0) continue;
            const size_t at = out.size();
            const size_t room = std::min(
                {size - at, out.capacity() - at, static_cast<size_t>(proc::kAnswerPipeBytes)});
            ssize_t n;
            if (room > 0) {
                out.resize(at + room);
                n = read(fd, out.data() + at, room);
                out.resize(at + static_cast<size_t>(std::max<ssize_t>(n, 0)));
            } else if ((n = read(fd, spare, std::min(sizeof spare, size - at))) > 0) {
                out.append(spare, static_cast<size_t>(n));
            }
            if (n == 0) return true;
            if (n < 0 && errno != EINTR && errno != EAGAIN)
                fail("cannot read the STEP/IGES reader's answer (" +
                     std::string(std::strerror(errno)) + ")");
        }
        return true;
    }

    const std::string& file_;
    proc::RequestPipes pipes_;
    pid_t pid_ = -1;
    bool ended_ = false;
    std::string status_bytes_;
};

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
    if (!answer.empty() && answer[0] == proc::kModelAnswer) {
        std::uint64_t size = 0;
        if (answer.size() >= kHead) std::memcpy(&size, answer.data() + 1, sizeof size);
        if (answer.size() < kHead || size != answer.size() - kHead)
            throw InputError(file, "",
                             "the STEP/IGES reader's answer is malformed (" +
                                 std::to_string(answer.size()) + " bytes, a model of " +
                                 std::to_string(size) + ")");
        try {
            return read_model_exchange(std::string_view(answer).substr(kHead), file,
                                       options.limits);
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
    Worker worker(file, options);
    std::string answer;
    int status = 0;
    if (!worker.run(deadline, answer, status))
        throw InputError(file, "",
                         "OpenCASCADE took longer than the time limit of " +
                             limit_text(limit, " s") +
                             " reading it (ModelLoadOptions::reader_time_limit)");
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
