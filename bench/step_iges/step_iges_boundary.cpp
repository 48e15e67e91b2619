// SPDX-License-Identifier: MIT
// Read time of STEP/IGES files with and without the process boundary, in one
// run: each file is read in this process (the reader linked in, OpenCASCADE
// loaded once, as the library did before issue 31) and through
// read_step_iges (a reader process per file), alternately, `--repeat N`
// times each; the minimum of each is kept. Both must give the same model,
// byte for byte in the exchange form, or the same error line. Prints a
// Markdown table (docs/results/step_iges_boundary.md).
#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges.h>
#include <seamless/model/step_iges/read_in_process.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace seamless;

// The seconds of one read and what it gave: the model's exchange bytes with
// its warnings, or the error line.
double timed(const std::function<Model()>& read, std::string& result) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
        result = "model " + write_model_exchange(read());
    } catch (const InputError& e) {
        result = std::string("error ") + e.what();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main(int argc, char** argv) {
    int repeat = 3;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
            repeat = std::atoi(argv[++i]);
        else
            files.push_back(argv[i]);
    }
    if (files.empty() || repeat < 1) {
        std::fprintf(stderr, "usage: step_iges_boundary [--repeat N] FILE...\n");
        return 2;
    }
    const ModelLoadOptions options;
    std::string warm;
    timed([&] { return step_iges::read_step_iges_in_process(files[0], options); }, warm);
    std::printf("| file | in process (s) | boundary (s) | cost (ms) | cost (%%) | within budget | "
                "same result |\n| --- | ---: | ---: | ---: | ---: | --- | --- |\n");
    int over = 0, differ = 0;
    for (const std::string& f : files) {
        double here = 1e300, there = 1e300;
        std::string a, b;
        for (int k = 0; k < repeat; ++k) {
            here = std::min(
                here, timed([&] { return step_iges::read_step_iges_in_process(f, options); }, a));
            there = std::min(there, timed([&] { return read_step_iges(f, options); }, b));
        }
        const double cost = there - here;
        const bool within = cost <= std::max(0.05 * here, 0.020);
        over += !within;
        differ += a != b;
        const std::string name = f.substr(f.find_last_of('/') + 1);
        std::printf("| %s | %.3f | %.3f | %.1f | %.1f | %s | %s |\n", name.c_str(), here, there,
                    1e3 * cost, 100 * cost / here, within ? "yes" : "**no**",
                    a == b ? (a.rfind("error", 0) == 0 ? "yes (error)" : "yes") : "**no**");
        std::fflush(stdout);
    }
    std::printf("\n%zu files, %d over the budget, %d with a different result\n", files.size(), over,
                differ);
    return differ ? 1 : 0;
}
