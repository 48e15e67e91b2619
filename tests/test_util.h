// SPDX-License-Identifier: MIT
// Helpers shared by the tests: paths to bundled data and running the CLI.
#pragma once

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <type_traits>
#include <unistd.h>

namespace seamless::test {

inline std::filesystem::path data_dir() {
    return SEAMLESS_DATA_DIR;
}
inline std::filesystem::path shared_dir() {
    return SEAMLESS_SHARED_DIR;
}
inline std::filesystem::path model_path(const std::string& name) {
    return data_dir() / "models" / name;
}

// The same object representation, byte for byte (so -0 and +0 differ): for
// "bit for bit" checks of values made of doubles without padding.
template <class T> bool same_bytes(const T& a, const T& b) {
    static_assert(std::is_trivially_copyable_v<T>);
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// A fresh, empty scratch directory under the test's working directory.
inline std::filesystem::path scratch_dir(const std::string& name) {
    auto p = std::filesystem::current_path() / ("scratch-" + name);
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

// The path in double quotes, for the shell. (Built by appending: GCC 12 warns
// -Wrestrict, wrongly, on "\"" + s + "\"".)
inline std::string quoted(const std::filesystem::path& p) {
    std::string s(1, '"');
    s += p.string();
    s += '"';
    return s;
}

struct RunResult {
    int status = -1;
    std::string out, err;
};

// Runs the seamless CLI with `args` (shell-quoted by the caller). Its output
// goes through files named after the process and a counter, so test cases
// that ctest runs in parallel in one folder never read each other's output.
inline RunResult run_cli(const std::string& args, const std::string& tag = "run") {
    static int calls = 0;
    auto dir = std::filesystem::current_path();
    const std::string base = tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(++calls);
    auto out = dir / (base + ".stdout"), err = dir / (base + ".stderr");
    std::string cmd = std::string("\"") + SEAMLESS_CLI + "\" " + args + " >\"" + out.string() +
                      "\" 2>\"" + err.string() + "\" </dev/null";
    int rc = std::system(cmd.c_str());
    RunResult r;
    r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    std::ifstream o(out), e(err);
    std::stringstream so, se;
    so << o.rdbuf();
    se << e.rdbuf();
    r.out = so.str();
    r.err = se.str();
    std::error_code ec;
    std::filesystem::remove(out, ec);
    std::filesystem::remove(err, ec);
    return r;
}

// A version-1 JSON model of one bilinear surface with the given control
// points (a JSON array of four [x, y, z]).
inline std::string bilinear_model(const std::string& points) {
    return R"({"version": 1, "surfaces": [{"degree": [1, 1], "size": [2, 2],
      "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1], "control_points": )" +
           points + "}]}";
}

} // namespace seamless::test
