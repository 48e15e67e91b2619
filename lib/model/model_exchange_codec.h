// SPDX-License-Identifier: MIT
// The writer and the reader of the model exchange form (model_exchange.h),
// shared by the files that write and read its parts: model_exchange.cpp (the
// model, its surfaces and curves), model_exchange_brep.cpp (the B-rep) and
// model_exchange_assembly.cpp (the assembly and its layers). Layout: the tag,
// then the members in the order of their declaration; a list is its count
// (8 bytes) and its elements; a string is its length and its bytes; int is 4
// bytes, bool 1, double its 8 bytes of IEEE 754.
#pragma once

#include <seamless/base/error.h>
#include <seamless/model/model_exchange.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace seamless::exchange {

inline constexpr std::string_view kTag = "seamless-model-exchange 2\n";

static_assert(sizeof(Vec3) == 3 * sizeof(double), "points are written as their doubles");

// Writes a model's bytes to one of three ends: counted only, kept in `out`,
// or handed to a sink in pieces of kPiece bytes (an array of a piece or more
// straight from the model: the whole form is never held).
class ExchangeWriter {
  public:
    using Sink = std::function<bool(const char*, std::size_t)>;
    static constexpr std::size_t kPiece = std::size_t(1)
                                          << 20; // a pipe's worth (step_iges_process.h)

    // Counts only.
    ExchangeWriter() = default;
    // Keeps the bytes in `out`, reserved at `size`.
    explicit ExchangeWriter(std::size_t size) : keep_(true) { out.reserve(size); }
    // Hands the bytes to `sink` until it returns false.
    explicit ExchangeWriter(const Sink& sink) : keep_(true), sink_(&sink) { out.reserve(kPiece); }

    std::string out;
    std::uint64_t size() const { return size_; }
    // The rest to the sink; false when the sink refused a piece.
    bool finish() {
        flush();
        return ok_;
    }

    void bytes(const void* p, std::size_t n) {
        size_ += n;
        if (!keep_) return;
        if (sink_ && n >= kPiece) {
            flush();
            ok_ = ok_ && (*sink_)(static_cast<const char*>(p), n);
            return;
        }
        out.append(static_cast<const char*>(p), n);
        if (sink_ && out.size() >= kPiece) flush();
    }
    template <class T> void scalar(T x) {
        static_assert(std::is_arithmetic_v<T>);
        bytes(&x, sizeof x);
    }
    void count(std::size_t n) { scalar<std::uint64_t>(n); }
    void string(const std::string& s) {
        count(s.size());
        bytes(s.data(), s.size());
    }
    template <class T> void array(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        count(v.size());
        bytes(v.data(), v.size() * sizeof(T));
    }
    void ints(const std::vector<int>& v) {
        static_assert(sizeof(int) == sizeof(std::int32_t));
        array(v);
    }
    template <class T, class Each> void list(const std::vector<T>& v, Each each) {
        count(v.size());
        for (const T& x : v) each(x);
    }

    void model(const Model& m);
    void surface(const BSplineSurface& s);
    void curve(const BSplineCurve& c);
    void brep(const BRep& b);         // model_exchange_brep.cpp
    void assembly(const Assembly& a); // model_exchange_assembly.cpp

  private:
    void flush() {
        if (sink_ && !out.empty()) ok_ = ok_ && (*sink_)(out.data(), out.size());
        out.clear();
    }

    bool keep_ = false;
    const Sink* sink_ = nullptr;
    bool ok_ = true;
    std::uint64_t size_ = 0;
};

// A field's name, built only on failure (reading costs no string per item):
// "brep.edges[3].curve" is {&{nullptr, "brep.edges", 3}, "curve"}.
struct ExchangePath {
    const ExchangePath* parent = nullptr;
    const char* name = "";
    long long index = -1;

    std::string str() const; // model_exchange.cpp
};

// Reads what ExchangeWriter wrote, trusting nothing (model_exchange.h).
class ExchangeReader {
  public:
    using Path = ExchangePath;

    ExchangeReader(std::string_view bytes, const std::string& file, const ModelLimits& limits)
        : in_(bytes), file_(file), limits_(limits) {}

    [[noreturn]] void fail(const Path& field, const std::string& message) const;

    void tag() {
        if (in_.substr(0, kTag.size()) != kTag) fail({}, "not a model exchange (wrong tag)");
        at_ = kTag.size();
    }
    void end() const {
        if (at_ != in_.size())
            fail({}, std::to_string(in_.size() - at_) + " bytes after the model");
    }

    template <class T> T scalar(const Path& field) {
        T x;
        if (in_.size() - at_ < sizeof x) fail(field, "truncated at byte " + std::to_string(at_));
        std::memcpy(&x, in_.data() + at_, sizeof x);
        at_ += sizeof x;
        return x;
    }
    int integer(const Path& field) { return scalar<std::int32_t>(field); }
    bool flag(const Path& field) {
        const auto b = scalar<std::uint8_t>(field);
        if (b > 1) fail(field, "expected 0 or 1, got " + std::to_string(b));
        return b;
    }
    // A count of elements of at least `bytes_each` bytes, within `limit`.
    std::size_t count(const Path& field, long long limit, std::size_t bytes_each) {
        const auto n = scalar<std::uint64_t>(field);
        if (n > static_cast<std::uint64_t>(limit))
            fail(field, std::to_string(n) + " items exceed the limit of " + std::to_string(limit));
        if (n > (in_.size() - at_) / bytes_each)
            fail(field, std::to_string(n) + " items, more than the " +
                            std::to_string(in_.size() - at_) + " bytes left hold");
        return n;
    }
    std::size_t items(const Path& field, std::size_t bytes_each) {
        return count(field, limits_.max_brep_items, bytes_each);
    }
    std::string string(const Path& field) {
        const std::size_t n = count(field, limits_.max_file_bytes, 1);
        std::string s(in_.substr(at_, n));
        at_ += n;
        return s;
    }
    // A flat array of at most `limit` elements: one copy of its bytes.
    template <class T> std::vector<T> array(const Path& field, long long limit) {
        static_assert(std::is_trivially_copyable_v<T>);
        std::vector<T> v(count(field, limit, sizeof(T)));
        if (!v.empty())
            std::memcpy(static_cast<void*>(v.data()), in_.data() + at_, v.size() * sizeof(T));
        at_ += v.size() * sizeof(T);
        return v;
    }
    // Integers that are read as they are (validate_assembly checks them).
    std::vector<int> ints(const Path& field) { return array<int>(field, limits_.max_brep_items); }
    Vec3 point(const Path& field) {
        const double x = scalar<double>(field), y = scalar<double>(field);
        return {x, y, scalar<double>(field)};
    }
    // An index into a list of n, or -1 where `none` allows it.
    int index(const Path& field, std::size_t n, bool none = false) {
        const int i = integer(field);
        if ((i < 0 || static_cast<std::size_t>(i) >= n) && !(none && i == -1))
            fail(field, "index " + std::to_string(i) + " out of range 0.." +
                            std::to_string(static_cast<long long>(n) - 1));
        return i;
    }
    double number(const Path& field) {
        const auto x = scalar<double>(field);
        if (!std::isfinite(x)) fail(field, "not a finite number");
        return x;
    }

    const std::string& file() const { return file_; }
    const ModelLimits& limits() const { return limits_; }

    Model model();
    BSplineSurface surface(const Path& f);
    BSplineCurve curve(const Path& f);
    void brep(Model& m);        // model_exchange_brep.cpp
    void assembly(Assembly& a); // model_exchange_assembly.cpp

  private:
    std::string_view in_;
    std::size_t at_ = 0;
    const std::string& file_;
    const ModelLimits& limits_;
};

} // namespace seamless::exchange
