// SPDX-License-Identifier: MIT
// check.h: a failed SEAMLESS_CHECK aborts with the condition, its place and
// the message on stderr, in every build; a passing one does nothing; and
// SEAMLESS_DCHECK follows NDEBUG (this test is built with and without it).
#include <seamless/base/check.h>

#include <catch2/catch.hpp>

#include <csignal>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

// Runs f in a child process; its exit signal (0: none) and what it wrote to stderr.
template <class F> std::pair<int, std::string> in_child(F f) {
    int fds[2];
    REQUIRE(pipe(fds) == 0);
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        dup2(fds[1], 2);
        close(fds[0]);
        f();
        _exit(0);
    }
    close(fds[1]);
    std::string err;
    char buf[256];
    for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) err.append(buf, n);
    close(fds[0]);
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    return {WIFSIGNALED(status) ? WTERMSIG(status) : 0, err};
}

int index_in_range(int i, int n) {
    SEAMLESS_CHECK(i >= 0 && i < n, "index out of range");
    return i;
}

} // namespace

TEST_CASE("SEAMLESS_CHECK aborts with the condition and the message", "[check]") {
    const auto [sig, err] = in_child([] { index_in_range(7, 3); });
    CHECK(sig == SIGABRT);
    CHECK(err.find("internal error at") != std::string::npos);
    CHECK(err.find("check_test.cpp") != std::string::npos);
    CHECK(err.find("i >= 0 && i < n") != std::string::npos);
    CHECK(err.find("index out of range") != std::string::npos);
}

TEST_CASE("SEAMLESS_CHECK passes through when the condition holds", "[check]") {
    const auto [sig, err] = in_child([] { index_in_range(2, 3); });
    CHECK(sig == 0);
    CHECK(err.empty());
}

TEST_CASE("SEAMLESS_DCHECK is on exactly when NDEBUG is off", "[check]") {
    const auto [sig, err] = in_child([] { SEAMLESS_DCHECK(1 + 1 == 3, "costly invariant"); });
#ifdef NDEBUG
    CHECK(sig == 0);
#else
    CHECK(sig == SIGABRT);
    CHECK(err.find("costly invariant") != std::string::npos);
#endif
}
