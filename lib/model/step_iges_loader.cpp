// SPDX-License-Identifier: MIT
// STEP/IGES on demand: the OpenCASCADE reader (step_iges/) is a module of
// its own, libseamless_step_iges.so beside libseamless.so, loaded the first
// time a STEP or IGES file is read. A run that reads JSON or .bpt models
// never maps OpenCASCADE's libraries, whose loading costs every run start-up
// time ("leave out what a given scene does not need"; docs/results/tessellation.md).
// Where the reader is linked into the program itself (the static fuzz build),
// its entry is found there first.
#include <seamless/model/step_iges.h>

#include <seamless/base/error.h>

#include <dlfcn.h>

#include <mutex>

namespace seamless {
namespace {

using ReadEntry = void (*)(const std::filesystem::path*, const ModelLoadOptions*, Model*);
constexpr const char* kEntry = "seamless_read_step_iges";
constexpr const char* kModule = "libseamless_step_iges.so";

// The module's path: beside the file holding this code (libseamless.so).
std::filesystem::path module_path() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&module_path), &info) && info.dli_fname)
        return std::filesystem::path(info.dli_fname).parent_path() / kModule;
    return kModule; // the dynamic loader's search path
}

// The entry, or an empty pointer with `error` saying why. Loaded once; never
// unloaded (OpenCASCADE keeps process-wide tables).
ReadEntry find_entry(std::string& error) {
    static std::once_flag once;
    static ReadEntry entry = nullptr;
    static std::string why;
    std::call_once(once, [] {
        entry = reinterpret_cast<ReadEntry>(dlsym(RTLD_DEFAULT, kEntry));
        if (entry) return;
        const std::filesystem::path path = module_path();
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = dlerror();
            why =
                std::string("STEP/IGES support is not installed (") + (e ? e : path.string()) + ")";
            return;
        }
        entry = reinterpret_cast<ReadEntry>(dlsym(handle, kEntry));
        if (!entry) why = path.string() + " has no " + kEntry;
    });
    error = why;
    return entry;
}

} // namespace

bool is_step_iges_extension(const std::string& ext) {
    return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

Model read_step_iges(const std::filesystem::path& path, const ModelLoadOptions& options) {
    std::string error;
    const ReadEntry read = find_entry(error);
    if (!read) throw InputError(path.string(), "", error);
    Model m;
    read(&path, &options, &m);
    return m;
}

} // namespace seamless
