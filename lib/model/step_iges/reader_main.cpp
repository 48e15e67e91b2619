// SPDX-License-Identifier: MIT
// seamless-step-iges: reads one STEP or IGES file with OpenCASCADE and answers
// the library that ran it (step_iges_process.h: arguments, answer, exit
// statuses). A crash here is this process's end, which the library reports as
// one line naming the file; the caller's process goes on.
#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>
#include <seamless/model/step_iges/read_in_process.h>
#include <seamless/model/step_iges_process.h>

#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <new>

namespace {

namespace proc = seamless::step_iges_process;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// No core file of a crash (the library reports it), and the memory limit:
// past it allocations fail, which ends the read as kOutOfMemory. ASan's
// shadow memory alone takes terabytes of address space, so its builds have
// no limit.
void limit_self(std::uint64_t memory_bytes) {
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    if (memory_bytes == 0 || kAddressSanitizer) return;
    rlimit as{};
    getrlimit(RLIMIT_AS, &as);
    const rlim_t want = static_cast<rlim_t>(memory_bytes);
    as.rlim_cur = std::min(as.rlim_max, want); // never above what the caller was given
    setrlimit(RLIMIT_AS, &as);
}

bool write_all(int fd, const std::string& s) {
    size_t done = 0;
    while (done < s.size()) {
        const ssize_t n = write(fd, s.data() + done, s.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    // A caller killed meanwhile takes its reader along.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    seamless::ModelLoadOptions options;
    if (argc != 3 || !proc::decode_options(argv[1], options)) {
        std::fprintf(stderr, "seamless-step-iges: run by libseamless to read a STEP or IGES "
                             "file (lib/model/step_iges_process.h), not by hand\n");
        return proc::kUsage;
    }
    limit_self(options.reader_memory_limit);
    std::string answer;
    try {
        answer = "M" + seamless::write_model_exchange(
                           seamless::step_iges::read_step_iges_in_process(argv[2], options));
    } catch (const seamless::InputError& e) {
        answer = proc::encode_error(e);
    } catch (const std::bad_alloc&) {
        _exit(proc::kOutOfMemory);
    }
    // _exit: OpenCASCADE's global tables need no tearing down.
    _exit(write_all(proc::kAnswerFd, answer) ? 0 : 1);
}
