// SPDX-License-Identifier: MIT
// STEP/IGES behind the process boundary (step_iges.h): OpenCASCADE's crashes
// on the reproducers (../shared/reproducers and the fuzzer's since), a time-out and a memory
// blow-up end as one InputError naming the file; the calling process never
// maps OpenCASCADE; reads from several threads at once give the same models.
#include "step_iges_reproducers.h"
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges.h>

#include <catch2/catch.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

using namespace seamless;

namespace {

std::string error_of(const std::filesystem::path& file, const ModelLoadOptions& options = {}) {
    try {
        load_model(file, options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool maps_opencascade() {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line))
        if (line.find("libTK") != std::string::npos) return true;
    return false;
}

// What a shell command prints on stdout; it must succeed.
std::string output_of(const std::string& command) {
    std::FILE* p = popen(command.c_str(), "r");
    REQUIRE(p);
    std::string out;
    char buf[4096];
    while (size_t k = std::fread(buf, 1, sizeof buf, p)) out.append(buf, k);
    REQUIRE(pclose(p) == 0);
    return out;
}

// The dynamic symbols of an ELF file that nm lists with `which`: names without versions.
std::set<std::string> dynamic_symbols(const std::string& file, const char* which) {
    std::istringstream lines(output_of("nm -D " + std::string(which) + " " + test::quoted(file)));
    std::set<std::string> names;
    for (std::string line; std::getline(lines, line);)
        if (const size_t space = line.rfind(' '); space != std::string::npos)
            names.insert(line.substr(space + 1, line.find('@', space) - space - 1));
    return names;
}

std::filesystem::path corpus(const std::string& name) {
    return test::shared_dir() / "models" / "cad-corpus" / name;
}

} // namespace

TEST_CASE("OpenCASCADE's crashes on the reproducers are one InputError naming the file",
          "[model][step_iges][heavy]") {
    const auto files = test::step_iges_reproducers();
    REQUIRE(files.size() >= 7);
    for (const auto& f : files) {
        INFO(f);
        const std::string e = error_of(f);
        CHECK_THAT(e, Catch::StartsWith(f.string() + ": OpenCASCADE crashed reading it (signal"));
        CHECK(e.find('\n') == std::string::npos);
    }
    // This process read STEP and IGES without mapping OpenCASCADE.
    CHECK_FALSE(maps_opencascade());
}

TEST_CASE("A good file read after a crash, and from four threads at once, gives one model",
          "[model][step_iges][heavy]") {
    const auto torus = test::model_path("cad/torus.igs");
    const std::string expected = write_model_exchange(load_model(torus));
    const auto crasher = test::step_iges_reproducers().front();
    std::vector<std::string> got(8);
    std::vector<std::thread> threads;
    for (size_t k = 0; k < got.size(); ++k)
        threads.emplace_back([&, k] {
            if (k % 2)
                got[k] = error_of(crasher);
            else
                got[k] = write_model_exchange(load_model(torus));
        });
    for (auto& t : threads) t.join();
    for (size_t k = 0; k < got.size(); ++k) {
        INFO(k);
        if (k % 2)
            CHECK_THAT(got[k], Catch::Contains("OpenCASCADE crashed reading it"));
        else
            CHECK(got[k] == expected);
    }
    CHECK_FALSE(maps_opencascade());
}

TEST_CASE("The reader's time limit ends a long read with one line", "[model][step_iges][heavy]") {
    ModelLoadOptions o;
    o.reader_time_limit = 0.005;
    const auto f = corpus("b123d_M6-1x12-countersunk-screw.step");
    CHECK(error_of(f, o) == f.string() +
                                ": OpenCASCADE took longer than the time limit of 0.005 s reading "
                                "it (ModelLoadOptions::reader_time_limit)");
    // The reader goes on serving: the same file within the default limit.
    CHECK_FALSE(load_model(f).surfaces.empty());
}

TEST_CASE("The reader's memory limit ends a read that needs more with one line",
          "[model][step_iges][heavy][native-allocator]") {
    // Below what OpenCASCADE has mapped already: its first allocations past
    // the heap the worker started with fail (a file as small as the torus
    // may need none).
    ModelLoadOptions o;
    o.reader_memory_limit = std::uint64_t(16) << 20;
    const auto f = test::model_path("cad/b123d_M6-1x12-countersunk-screw.step");
    CHECK(error_of(f, o) == f.string() +
                                ": OpenCASCADE ran out of memory reading it (the reader's limit is "
                                "16 MiB, ModelLoadOptions::reader_memory_limit)");
    CHECK_FALSE(load_model(f).surfaces.empty());
}

TEST_CASE("A memory blow-up under any limit says it ran out of the limit, never that the file "
          "is unreadable",
          "[model][step_iges][heavy][native-allocator]") {
    // OpenCASCADE's STEP reader catches its own failed allocations and says
    // "not a readable STEP file" (11752 below about 100 MiB): the worker
    // tells it by the allocations that failed.
    for (const auto& f : {corpus("pyocc_11752.stp"), corpus("occt_bearing.iges")})
        for (int mib = 8; mib <= 88; mib += 16) {
            INFO(f << " " << mib << " MiB");
            ModelLoadOptions o;
            o.reader_memory_limit = std::uint64_t(mib) << 20;
            const std::string e = error_of(f, o);
            if (e.empty()) continue; // enough for this file
            CHECK(e == f.string() +
                           ": OpenCASCADE ran out of memory reading it (the reader's limit is " +
                           std::to_string(mib) + " MiB, ModelLoadOptions::reader_memory_limit)");
        }
}

TEST_CASE("The reader's server runs with the caller's environment and malloc on huge pages",
          "[model][step_iges][heavy]") {
    load_model(test::model_path("cad/torus.igs")); // the server started
    std::string environment;
    for (const auto& e : std::filesystem::directory_iterator("/proc")) {
        std::ifstream stat(e.path() / "stat");
        std::string line;
        if (!std::getline(stat, line) || line.find("(seamless-step-i") == std::string::npos)
            continue;
        std::istringstream fields(line.substr(line.rfind(')') + 2));
        std::string state;
        pid_t parent = 0;
        fields >> state >> parent;
        if (parent != getpid()) continue;
        std::ifstream in(e.path() / "environ");
        std::getline(in, environment, '\x01'); // NUL-separated: all of it
    }
    REQUIRE_FALSE(environment.empty());
    CHECK_THAT(environment, Catch::Contains("glibc.malloc.hugetlb="));
    const char* path = std::getenv("PATH");
    REQUIRE(path != nullptr);
    CHECK_THAT(environment, Catch::Contains(std::string("PATH=") + path));
}

TEST_CASE("An InputError of the reader reaches the caller as it was raised",
          "[model][step_iges][heavy]") {
    const auto dir = test::scratch_dir("boundary-error");
    const auto f = dir / "empty.step";
    test::write_file(f, "ISO-10303-21;\nEND-ISO-10303-21;\n");
    try {
        load_model(f);
        FAIL("read");
    } catch (const InputError& e) {
        CHECK(e.file() == f.string());
        CHECK_THAT(e.message(), !Catch::Contains("crashed") && !Catch::Contains("malformed"));
    }
}

TEST_CASE("Every allocation function the reader's libraries call is the reader's own, which "
          "watches it for a memory blow-up",
          "[model][step_iges][heavy][native-allocator]") {
    // The reader is beside the library (step_iges_server.cpp).
    Dl_info info{};
    REQUIRE(dladdr(reinterpret_cast<void*>(&read_model_exchange), &info));
    const auto reader = std::filesystem::path(info.dli_fname).parent_path() / "seamless-step-iges";
    const std::set<std::string> own = dynamic_symbols(reader, "--defined-only");
    const std::set<std::string> allocators = {"malloc",         "calloc",        "realloc",
                                              "posix_memalign", "aligned_alloc", "memalign",
                                              "valloc",         "pvalloc"};
    // ldd: "libTKernel.so.7 => /usr/lib/.../libTKernel.so.7 (0x...)", each library it loads.
    std::istringstream libraries(output_of("ldd " + test::quoted(reader)));
    int opencascade = 0;
    std::set<std::string> called;
    for (std::string line; std::getline(libraries, line);) {
        const size_t arrow = line.find("=> /");
        if (arrow == std::string::npos || line.find("/libc.so") != std::string::npos) continue;
        const std::string library = line.substr(arrow + 3, line.find(" (", arrow) - arrow - 3);
        opencascade += library.find("libTK") != std::string::npos;
        for (const std::string& f : dynamic_symbols(library, "--undefined-only"))
            if (allocators.count(f)) {
                INFO(library << " calls " << f);
                CHECK(own.count(f) == 1);
                called.insert(f);
            }
    }
    CHECK(opencascade > 10);
    CHECK(called.count("malloc") == 1);
    CHECK(called.count("posix_memalign") == 1); // TKernel's aligned allocations
}
