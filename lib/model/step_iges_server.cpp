// SPDX-License-Identifier: MIT
// Starting the STEP/IGES reader's server and handing it requests
// (step_iges_server.h). A request is one datagram of a SOCK_SEQPACKET socket
// (so requests of several threads never interleave) carrying the options,
// the file name and, as SCM_RIGHTS, the write ends of its two pipes.
#include <seamless/model/step_iges_server.h>

#include <seamless/base/error.h>
#include <seamless/model/step_iges_process.h>

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

extern char** environ;

namespace seamless::step_iges_process {
namespace {

constexpr const char* kHugePages = "glibc.malloc.hugetlb=1";

// The reader's path: beside the file holding this code (libseamless.so, or
// the program itself where the library is linked in, as in the fuzz build).
std::filesystem::path reader_path() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&reader_path), &info) && info.dli_fname)
        return std::filesystem::path(info.dli_fname).parent_path() / kExecutable;
    return kExecutable;
}

// The server's environment: the caller's, with glibc's malloc asked to back
// its heap with transparent huge pages (docs/results/step_iges_boundary.md: a
// worker's heap starts empty, and its first touches of 4-KiB pages were a
// good part of the boundary's cost). A caller's own malloc tunables are kept.
std::vector<std::string> server_environment() {
    std::vector<std::string> env;
    bool tunables = false;
    for (char** e = environ; *e; ++e) {
        std::string v = *e;
        if (v.rfind("GLIBC_TUNABLES=", 0) == 0) {
            tunables = true;
            if (v.find("glibc.malloc.hugetlb") == std::string::npos)
                v += (v.size() > 15 ? ":" : "") + std::string(kHugePages);
        }
        env.push_back(std::move(v));
    }
    if (!tunables) env.push_back(std::string("GLIBC_TUNABLES=") + kHugePages);
    return env;
}

struct Server {
    std::mutex mutex;
    pid_t pid = -1;
    int socket = -1;

    // Starts the server; the error, empty on success.
    std::string start() {
        if (socket >= 0) close(socket);
        if (pid > 0) waitpid(pid, nullptr, WNOHANG); // a server that ended: reaped
        socket = -1;
        pid = -1;
        int sv[2];
        // Close-on-exec: no other child of the caller keeps the server alive.
        if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sv) != 0)
            return std::string("socketpair: ") + std::strerror(errno);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, sv[1], kServerFd);
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
        const std::string exe = reader_path().string();
        char* argv[] = {const_cast<char*>(exe.c_str()), const_cast<char*>(kServerArgument),
                        nullptr};
        std::vector<std::string> env = server_environment();
        std::vector<char*> envp;
        for (std::string& v : env) envp.push_back(v.data());
        envp.push_back(nullptr);
        const int rc = posix_spawn(&pid, exe.c_str(), &actions, &attr, argv, envp.data());
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attr);
        close(sv[1]);
        if (rc != 0) {
            close(sv[0]);
            pid = -1;
            return "STEP/IGES support is not installed (cannot run " + exe + ": " +
                   std::strerror(rc) + ")";
        }
        socket = sv[0];
        return {};
    }

    // Sends the request with the two write ends; false when the server is gone.
    bool send(const std::string& payload, int answer, int status) const {
        iovec iov{const_cast<char*>(payload.data()), payload.size()};
        alignas(cmsghdr) char control[CMSG_SPACE(2 * sizeof(int))] = {};
        msghdr msg{};
        msg.msg_iov = &iov;
        msg.msg_iovlen = 1;
        msg.msg_control = control;
        msg.msg_controllen = sizeof control;
        cmsghdr* c = CMSG_FIRSTHDR(&msg);
        c->cmsg_level = SOL_SOCKET;
        c->cmsg_type = SCM_RIGHTS;
        c->cmsg_len = CMSG_LEN(2 * sizeof(int));
        const int fds[2] = {answer, status};
        std::memcpy(CMSG_DATA(c), fds, sizeof fds);
        ssize_t n;
        while ((n = sendmsg(socket, &msg, MSG_NOSIGNAL)) < 0 && errno == EINTR) {
        }
        return n == static_cast<ssize_t>(payload.size());
    }
};

Server& server() {
    static Server* s = new Server; // never destroyed: the server ends with the caller
    return *s;
}

} // namespace

RequestPipes request_read(const std::string& file, const ModelLoadOptions& options) {
    int answer[2], status[2];
    if (pipe2(answer, O_CLOEXEC) != 0)
        throw InputError(file, "",
                         std::string("cannot start the STEP/IGES reader (pipe: ") +
                             std::strerror(errno) + ")");
    if (pipe2(status, O_CLOEXEC) != 0) {
        const int e = errno;
        close(answer[0]);
        close(answer[1]);
        throw InputError(file, "",
                         std::string("cannot start the STEP/IGES reader (pipe: ") +
                             std::strerror(e) + ")");
    }
    fcntl(answer[0], F_SETPIPE_SZ, kAnswerPipeBytes); // a failure leaves the default
    const std::string payload = encode_options(options) + '\0' + file;
    std::string error;
    bool sent = false;
    {
        Server& s = server();
        std::lock_guard<std::mutex> lock(s.mutex);
        // A server that has ended (killed by someone) is started again, once.
        for (int attempt = 0; attempt < 2 && !sent && error.empty(); ++attempt) {
            if (s.socket < 0 || attempt > 0) error = s.start();
            if (error.empty()) sent = s.send(payload, answer[1], status[1]);
        }
    }
    close(answer[1]);
    close(status[1]);
    if (!sent) {
        close(answer[0]);
        close(status[0]);
        throw InputError(file, "",
                         error.empty() ? "the STEP/IGES reader's server does not take requests"
                                       : error);
    }
    return {answer[0], status[0]};
}

} // namespace seamless::step_iges_process
