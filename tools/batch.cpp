// SPDX-License-Identifier: MIT
// seamless batch INPUTS... -o OUT_DIR: the batch runner is the Python
// module's (python/seamless/batch, docs/batch.md), one implementation; this
// command runs it with Debian's python3, this program as the per-file worker
// and this build's module first on the path.
#include "commands.h"

#include <seamless/base/error.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace seamless::cli {
namespace {

int run_batch(const std::vector<std::string>& args) {
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
    // build/bin/seamless -> build/python (where the build puts the module).
    const std::string module_dir = (self.parent_path().parent_path() / "python").string();
    const char* old_path = std::getenv("PYTHONPATH");
    const std::string path =
        module_dir + (old_path && *old_path ? ":" + std::string(old_path) : "");
    ::setenv("PYTHONPATH", path.c_str(), 1);
    ::setenv("SEAMLESS_CLI", self.c_str(), 0);
    const char* python_env = std::getenv("SEAMLESS_PYTHON");
    const std::string python = python_env && *python_env                 ? python_env
                               : ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3"
                                                                         : "python3";
    std::vector<char*> argv{const_cast<char*>(python.c_str()), const_cast<char*>("-m"),
                            const_cast<char*>("seamless.batch")};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    throw InputError("", "batch", python + ": " + std::strerror(errno));
}

} // namespace

void add_batch(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand(
        "batch", "Tessellate (and check) many model files, each in its own process with time "
                 "and memory limits, into OUT_DIR with a resumable manifest; on this machine or "
                 "a Dask cluster (seamless batch --help, docs/batch.md)");
    // Every argument, --help included, goes to the Python runner's own parser.
    cmd->prefix_command();
    cmd->set_help_flag();
    cmd->callback([&action, cmd] {
        auto args = std::make_shared<std::vector<std::string>>(cmd->remaining());
        action = [args] { return run_batch(*args); };
    });
}

} // namespace seamless::cli
