// SPDX-License-Identifier: MIT
#include "model_options.h"
#include "number_options.h"

#include <cctype>
#include <iostream>

namespace seamless::cli {

void add_model_options(CLI::App* cmd, ModelLoadOptions& options) {
    auto* skip = cmd->add_flag_callback(
        "--skip-trimmed", [&options] { options.trimmed = TrimmedFaces::skip; },
        "STEP/IGES: leave trimmed faces out (default: read them as trimmed B-rep faces)");
    auto* whole = cmd->add_flag_callback(
        "--untrimmed", [&options] { options.trimmed = TrimmedFaces::whole_surface; },
        "STEP/IGES: take the whole underlying surfaces of trimmed faces");
    skip->excludes(whole);
    add_reader_limits(cmd, options);
}

std::optional<std::uint64_t> parse_bytes(const std::string& text) {
    size_t digits = 0;
    while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
    // Up to 19 digits fit an uint64_t; the limit below is far smaller.
    if (digits == 0 || digits > 19 || text.size() > digits + 1) return std::nullopt;
    int shift = 0;
    if (text.size() == digits + 1) {
        const std::string units = "KMGT";
        const size_t k = units.find(static_cast<char>(std::toupper(text.back())));
        if (k == std::string::npos) return std::nullopt;
        shift = 10 * static_cast<int>(k + 1);
    }
    const std::uint64_t n = std::stoull(text.substr(0, digits));
    constexpr std::uint64_t kMax = std::uint64_t(1) << 62; // beyond any address space
    if (n > (kMax >> shift)) return std::nullopt;
    return n << shift;
}

void add_reader_limits(CLI::App* cmd, ModelLoadOptions& options) {
    // Shown as "SECONDS=600" and "BYTES=4096M": the validators' own
    // descriptions would repeat the type.
    cmd->add_option("--reader-time-limit", options.reader_time_limit,
                    "STEP/IGES: stop OpenCASCADE's read of a file after this many seconds of "
                    "wall-clock time (exit 2; 0: no limit)")
        ->type_name("SECONDS")
        ->check(finite_number(Bound::non_negative).description(""))
        ->capture_default_str();
    const CLI::Validator bytes(
        [](std::string& s) -> std::string {
            return parse_bytes(s) ? std::string()
                                  : "expected bytes: an integer up to 2^62, optionally with K, M, "
                                    "G or T (powers of 1024), got '" +
                                        s + "'";
        },
        "");
    cmd->add_option_function<std::string>(
           "--reader-memory-limit",
           [&options](const std::string& s) { options.reader_memory_limit = *parse_bytes(s); },
           "STEP/IGES: stop OpenCASCADE's read of a file past this much address space (exit 2; "
           "K, M, G, T: powers of 1024; 0: no limit)")
        ->type_name("BYTES")
        ->check(bytes)
        ->default_str(std::to_string(ModelLoadOptions{}.reader_memory_limit >> 20) + "M");
}

void print_warnings(const Model& m) {
    for (const std::string& w : m.warnings) std::cerr << "warning: " << w << "\n";
}

} // namespace seamless::cli
