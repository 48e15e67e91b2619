// SPDX-License-Identifier: MIT
// seamless-step-iges --server: the STEP/IGES reader's server
// (step_iges_process.h). It loads OpenCASCADE and initialises its STEP and
// IGES readers once, then forks a worker per request, which reads one file
// and answers. A crash is the worker's end, which the library reports as one
// line naming the file; the server and the caller go on. The server is
// single-threaded, so fork is safe here.
#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges/read_in_process.h>
#include <seamless/model/step_iges_process.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/signalfd.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define SEAMLESS_READER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SEAMLESS_READER_ASAN 1
#endif
#endif
#ifndef SEAMLESS_READER_ASAN
#define SEAMLESS_READER_ASAN 0
#endif

namespace {

namespace proc = seamless::step_iges_process;

constexpr bool kAddressSanitizer = SEAMLESS_READER_ASAN;

// Set when an allocation has failed in this process. OpenCASCADE's file
// readers catch their own failed allocations and report the file unreadable
// (11752 under a limit of 72 MiB: "not a readable STEP file"), so the worker
// cannot tell a memory blow-up from its outcome: it watches malloc instead.
std::atomic<bool> allocation_failed{false}; // OpenCASCADE may allocate in threads

} // namespace

#if !SEAMLESS_READER_ASAN
namespace {
void* watched(void* p) {
    if (!p) allocation_failed.store(true, std::memory_order_relaxed);
    return p;
}
} // namespace

// glibc's allocator under this executable's allocation functions, which
// every library's calls resolve to (ASan has its own allocator: not there):
// those that OpenCASCADE and the libraries it loads call (nm -D: malloc,
// calloc and realloc everywhere, posix_memalign in TKernel's aligned
// allocations, aligned_alloc in libstdc++'s aligned new, memalign in TBB's).
extern "C" {
void* __libc_malloc(size_t size);
void* __libc_calloc(size_t n, size_t size);
void* __libc_realloc(void* p, size_t size);
void* __libc_memalign(size_t alignment, size_t size);

void* malloc(size_t size) noexcept {
    return watched(__libc_malloc(size));
}
void* calloc(size_t n, size_t size) noexcept {
    return watched(__libc_calloc(n, size));
}
void* realloc(void* p, size_t size) noexcept {
    void* q = __libc_realloc(p, size);
    return size == 0 ? q : watched(q); // realloc(p, 0) frees p
}
void* memalign(size_t alignment, size_t size) noexcept {
    return watched(__libc_memalign(alignment, size));
}
void* aligned_alloc(size_t alignment, size_t size) noexcept { // glibc 2.36's is memalign's
    return watched(__libc_memalign(alignment, size));
}
int posix_memalign(void** p, size_t alignment, size_t size) noexcept {
    if (alignment == 0 || alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0)
        return EINVAL;
    void* q = watched(__libc_memalign(alignment, size));
    if (!q) return ENOMEM;
    *p = q;
    return 0;
}
}
#endif

namespace {

std::uint64_t memory_limit = 0; // bytes of address space; 0: none

// The worker's address space, in bytes, from /proc/self/statm (with
// async-signal-safe calls only: it is read in a signal handler).
std::uint64_t address_space() {
    const int fd = open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return 0;
    char buf[64];
    const ssize_t n = read(fd, buf, sizeof buf);
    close(fd);
    std::uint64_t pages = 0;
    for (ssize_t i = 0; i < n && buf[i] >= '0' && buf[i] <= '9'; ++i)
        pages = 10 * pages + static_cast<std::uint64_t>(buf[i] - '0');
    return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// OpenCASCADE does not check every allocation: past the memory limit it
// dereferences the null pointer malloc returned (errno ENOMEM), or the stack
// cannot grow. Such a crash is reported as running out of memory.
void on_crash(int sig) {
    const int e = errno;
    if (e == ENOMEM || address_space() + (std::uint64_t(1) << 20) >= memory_limit)
        _exit(proc::kOutOfMemory);
    signal(sig, SIG_DFL);
    raise(sig);
}

// No core file of a crash (the library reports it), and the memory limit:
// past it allocations fail, which ends the read as kOutOfMemory. ASan's
// shadow memory alone takes terabytes of address space, so its builds have
// no limit (and keep ASan's own crash reports).
void limit_self(std::uint64_t memory_bytes) {
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    if (memory_bytes == 0 || kAddressSanitizer) return;
    rlimit as{};
    getrlimit(RLIMIT_AS, &as);
    as.rlim_cur =
        std::min(as.rlim_max, static_cast<rlim_t>(memory_bytes)); // never above the caller's
    setrlimit(RLIMIT_AS, &as);
    memory_limit = as.rlim_cur;
    // The handler's own stack: the crash may be the stack's failure to grow.
    static char stack[1 << 16];
    const stack_t alt{stack, 0, sizeof stack};
    sigaltstack(&alt, nullptr);
    struct sigaction a = {};
    a.sa_handler = on_crash;
    a.sa_flags = SA_ONSTACK;
    for (int sig : {SIGSEGV, SIGBUS, SIGABRT}) sigaction(sig, &a, nullptr);
}

bool write_all(int fd, const void* data, size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

// The worker: reads `file` and answers on `answer`; never returns. The model
// goes out as its tag, its size and its bytes, streamed from the model
// (write_model_exchange's sink): building the whole form first cost a copy of
// it in fresh pages (26 MB for 11752; docs/results/step_iges_boundary.md).
[[noreturn]] void work(int answer, const seamless::ModelLoadOptions& options, const char* file) {
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    signal(SIGPIPE, SIG_DFL);
    prctl(PR_SET_PDEATHSIG, SIGKILL); // the server's end is the worker's
    limit_self(options.reader_memory_limit);
    std::string error;
    bool sent = false;
    try {
        // Never freed: the worker's _exit drops its heap at once.
        const auto* model =
            new seamless::Model(seamless::step_iges::read_step_iges_in_process(file, options));
        // Whatever the read made of a failed allocation (an error, or a model
        // without what it could not hold), it ran out of memory.
        if (allocation_failed.load()) _exit(proc::kOutOfMemory);
        char head[1 + sizeof(std::uint64_t)] = {proc::kModelAnswer};
        const std::uint64_t size = seamless::model_exchange_size(*model);
        std::memcpy(head + 1, &size, sizeof size);
        sent = write_all(answer, head, sizeof head) &&
               seamless::write_model_exchange(
                   *model, [&](const char* p, size_t n) { return write_all(answer, p, n); });
    } catch (const seamless::InputError& e) {
        error = proc::encode_error(e);
    } catch (const std::bad_alloc&) {
        _exit(proc::kOutOfMemory);
    }
    if (allocation_failed.load()) _exit(proc::kOutOfMemory); // and a read that ended in an error
    if (!error.empty()) sent = write_all(answer, error.data(), error.size());
    // _exit: OpenCASCADE's global tables need no tearing down.
    _exit(sent ? 0 : 1);
}

// One request: its payload and its two pipes' write ends (or -1).
struct Request {
    std::string options, file;
    int answer = -1, status = -1;
};

// The next request; false at the end of the socket (the callers are gone).
// A malformed one comes back with its pipes but without a file.
bool receive(Request& r) {
    static char buf[1 << 16];
    alignas(cmsghdr) char control[CMSG_SPACE(2 * sizeof(int))];
    iovec iov{buf, sizeof buf};
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    ssize_t n;
    while ((n = recvmsg(proc::kServerFd, &msg, MSG_CMSG_CLOEXEC)) < 0 && errno == EINTR) {
    }
    if (n <= 0) return false;
    r = Request{};
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c; c = CMSG_NXTHDR(&msg, c))
        if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS &&
            c->cmsg_len == CMSG_LEN(2 * sizeof(int))) {
            int fds[2];
            std::memcpy(fds, CMSG_DATA(c), sizeof fds);
            r.answer = fds[0];
            r.status = fds[1];
        }
    const std::string_view payload(buf, static_cast<size_t>(n));
    const size_t zero = payload.find('\0');
    if (zero != std::string_view::npos && !(msg.msg_flags & MSG_TRUNC)) {
        r.options = payload.substr(0, zero);
        r.file = payload.substr(zero + 1);
    }
    return true;
}

// Workers running: pid -> the write end of their status pipe.
std::map<pid_t, int> workers;

void start(const Request& r) {
    seamless::ModelLoadOptions options;
    const bool ok = r.answer >= 0 && !r.file.empty() && proc::decode_options(r.options, options);
    const pid_t pid = ok ? fork() : -1;
    if (pid == 0) {
        close(proc::kServerFd);
        work(r.answer, options, r.file.c_str());
    }
    if (r.answer >= 0) close(r.answer);
    // Not started: the status pipe closes without a pid, which the library reports.
    if (pid < 0 || !write_all(r.status, &pid, sizeof pid)) {
        if (r.status >= 0) close(r.status);
        return;
    }
    workers[pid] = r.status;
}

void reap() {
    int status;
    pid_t pid;
    while ((pid = waitpid(-1, &status, WNOHANG)) > 0) {
        const auto w = workers.find(pid);
        if (w == workers.end()) continue;
        write_all(w->second, &status, sizeof status); // a caller gone meanwhile: ignored
        close(w->second);
        workers.erase(w);
    }
}

int serve() {
    seamless::step_iges::prepare_reader();
    signal(SIGPIPE, SIG_IGN); // a caller that has given up on a read
    sigset_t chld;
    sigemptyset(&chld);
    sigaddset(&chld, SIGCHLD);
    sigprocmask(SIG_BLOCK, &chld, nullptr);
    const int children = signalfd(-1, &chld, SFD_CLOEXEC);
    if (children < 0) return 1;
    for (;;) {
        pollfd p[2] = {{proc::kServerFd, POLLIN, 0}, {children, POLLIN, 0}};
        if (poll(p, 2, -1) < 0) {
            if (errno == EINTR) continue;
            return 1;
        }
        if (p[1].revents & POLLIN) {
            signalfd_siginfo info;
            (void)!read(children, &info, sizeof info);
            reap();
        }
        if (p[0].revents & (POLLIN | POLLHUP | POLLERR)) {
            Request r;
            if (!receive(r)) break;
            start(r);
        }
    }
    return 0; // the workers end with the server (PR_SET_PDEATHSIG)
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2 || std::strcmp(argv[1], proc::kServerArgument) != 0) {
        std::fprintf(stderr, "seamless-step-iges: the STEP/IGES reader libseamless runs "
                             "(lib/model/step_iges_process.h), not a command\n");
        return proc::kUsage;
    }
    _exit(serve());
}
