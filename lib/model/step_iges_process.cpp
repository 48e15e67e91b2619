// SPDX-License-Identifier: MIT
// The arguments and the error answer of the STEP/IGES reader's process
// (step_iges_process.h).
#include <seamless/model/step_iges_process.h>

#include <charconv>
#include <cstdint>
#include <cstdio>

namespace seamless::step_iges_process {
namespace {

// A member added to ModelLoadOptions must be passed on below; the size
// (x86-64) stops the build until it is.
// keep_assembly is not passed on: the reader always returns the tree, and
// the caller's load_model places its instances.
static_assert(sizeof(ModelLoadOptions) == 80 && sizeof(ModelLimits) == 40,
              "a member was added to ModelLoadOptions: pass it on in step_iges_process.cpp");

void append_double(std::string& s, double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a ", x); // hexadecimal: read back exactly
    s += buf;
}
template <class Int> void append_integer(std::string& s, Int x) {
    s += std::to_string(x);
    s += ' ';
}

class Tokens {
  public:
    explicit Tokens(std::string_view t) : t_(t) {}
    template <class Int> bool integer(Int& x) {
        const std::string_view w = next();
        const auto r = std::from_chars(w.data(), w.data() + w.size(), x);
        return r.ec == std::errc() && r.ptr == w.data() + w.size() && !w.empty();
    }
    bool number(double& x) {
        const std::string w(next());
        char* end = nullptr;
        x = std::strtod(w.c_str(), &end);
        return !w.empty() && end == w.c_str() + w.size();
    }
    bool done() const { return t_.empty(); }

  private:
    std::string_view next() {
        const size_t space = t_.find(' ');
        const std::string_view w = t_.substr(0, space);
        t_.remove_prefix(space == std::string_view::npos ? t_.size() : space + 1);
        return w;
    }
    std::string_view t_;
};

void append_string(std::string& s, const std::string& x) {
    append_integer(s, static_cast<long long>(x.size()));
    s += x;
}

bool take_string(std::string_view& in, std::string& x) {
    const size_t space = in.find(' ');
    if (space == std::string_view::npos) return false;
    std::uint64_t n = 0;
    const auto r = std::from_chars(in.data(), in.data() + space, n);
    if (r.ec != std::errc() || r.ptr != in.data() + space || n > in.size() - space - 1)
        return false;
    x.assign(in.substr(space + 1, n));
    in.remove_prefix(space + 1 + n);
    return true;
}

} // namespace

std::string encode_options(const ModelLoadOptions& o) {
    std::string s;
    const ModelLimits& l = o.limits;
    for (long long x : {l.max_surfaces, l.max_control_points, l.max_brep_items, l.max_curve_points,
                        static_cast<long long>(o.trimmed)})
        append_integer(s, x);
    append_integer(s, l.max_file_bytes);
    append_integer(s, o.reader_memory_limit);
    append_double(s, o.approximation_tolerance);
    append_double(s, o.reader_time_limit);
    s.pop_back();
    return s;
}

bool decode_options(std::string_view text, ModelLoadOptions& o) {
    Tokens t(text);
    long long trimmed = 0;
    ModelLimits& l = o.limits;
    const bool ok = t.integer(l.max_surfaces) && t.integer(l.max_control_points) &&
                    t.integer(l.max_brep_items) && t.integer(l.max_curve_points) &&
                    t.integer(trimmed) && t.integer(l.max_file_bytes) &&
                    t.integer(o.reader_memory_limit) && t.number(o.approximation_tolerance) &&
                    t.number(o.reader_time_limit) && t.done();
    if (!ok || trimmed < 0 || trimmed > static_cast<long long>(TrimmedFaces::whole_surface))
        return false;
    o.trimmed = static_cast<TrimmedFaces>(trimmed);
    return true;
}

std::string encode_error(const InputError& e) {
    std::string s = "E";
    append_string(s, e.file());
    append_string(s, e.field());
    append_string(s, e.message());
    return s;
}

bool decode_error(std::string_view answer, std::string& file, std::string& field,
                  std::string& message) {
    if (answer.empty() || answer[0] != 'E') return false;
    answer.remove_prefix(1);
    return take_string(answer, file) && take_string(answer, field) &&
           take_string(answer, message) && answer.empty();
}

} // namespace seamless::step_iges_process
