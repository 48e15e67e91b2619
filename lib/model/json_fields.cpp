// SPDX-License-Identifier: MIT
#include <seamless/model/json_fields.h>

#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>

#include <charconv>
#include <cmath>
#include <sstream>

namespace seamless {
namespace {

// SAX handler that only tracks where in the document the parser is, so that an
// error nlohmann reports without a field (a number like 1e999 that overflows to
// infinity) can still be named: "surfaces[0].knots_u[3]".
class PathTracker : public nlohmann::json_sax<Json> {
  public:
    std::string path() const {
        std::string s;
        for (const Frame& f : stack_) {
            if (f.array)
                s += "[" + std::to_string(f.index) + "]";
            else if (!f.key.empty())
                s += (s.empty() ? "" : ".") + f.key;
        }
        return s;
    }
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return push(false); }
    bool key(string_t& k) override {
        stack_.back().key = k;
        return true;
    }
    bool end_object() override { return pop(); }
    bool start_array(std::size_t) override { return push(true); }
    bool end_array() override { return pop(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false;
    }

  private:
    struct Frame {
        bool array;
        size_t index = 0;
        std::string key;
    };
    bool value() {
        if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
        return true;
    }
    bool push(bool array) {
        stack_.push_back({array, 0, {}});
        return true;
    }
    bool pop() {
        stack_.pop_back();
        return value();
    }
    std::vector<Frame> stack_;
};

// "line 3, column 7" of a 1-based byte offset, as an editor shows it.
std::string line_and_column(const std::string& text, std::size_t byte1) {
    size_t byte = byte1 == 0 ? 0 : byte1 - 1, line = 1, col = 1;
    for (size_t k = 0; k < byte && k < text.size(); ++k) {
        if (text[k] == '\n')
            ++line, col = 1;
        else
            ++col;
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

std::string range_text(long long lo, long long hi) {
    return std::to_string(lo) + ".." + std::to_string(hi);
}

} // namespace

std::string member_field(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

std::string element_field(const std::string& array, std::size_t k) {
    return array + "[" + std::to_string(k) + "]";
}

void write_json_number(std::ostream& os, double x) {
    if (x == 0 && std::signbit(x)) {
        os << "-0.0";
        return;
    }
    char buf[32]; // printf's "%.17g", faster
    const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
    os.write(buf, r.ptr - buf);
}

void write_json_string(std::ostream& os, const std::string& s) {
    // Invalid UTF-8 (a hostile STEP name) is replaced, never thrown on.
    os << Json(s).dump(-1, ' ', false, Json::error_handler_t::replace);
}

void write_json_ints(std::ostream& os, const std::vector<int>& v) {
    os << '[';
    for (size_t i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
    os << ']';
}

void JsonFields::fail(const std::string& field, const std::string& message) const {
    throw InputError(file_, field, message);
}

Json JsonFields::parse_object(const std::string& text) const {
    Json root;
    try {
        root = naming_file_on_oom(file_, [&] { return Json::parse(text); });
    } catch (const Json::parse_error& e) {
        std::string what = e.what();
        auto pos = what.find("syntax error");
        fail(line_and_column(text, e.byte),
             "JSON " + (pos == std::string::npos ? what : what.substr(pos)));
    } catch (const Json::out_of_range&) {
        // JSON has no NaN or infinity, but 1e999 overflows to infinity.
        PathTracker where;
        Json::sax_parse(text, &where);
        fail(where.path(), "not a finite number (overflows a double)");
    }
    if (!root.is_object()) fail("", "expected a JSON object at the top level");
    return root;
}

int JsonFields::check_version(const Json& root, int newest) const {
    const Json& version = member(root, "version", "version");
    const long long v = integer(version, "version", 0, 1'000'000);
    if (v < 1 || v > newest) {
        std::string known = "1";
        for (int k = 2; k <= newest; ++k)
            known += (k == newest ? " and " : ", ") + std::to_string(k);
        fail("version",
             "unsupported version " + version.dump() + " (this reader knows " + known + ")");
    }
    return static_cast<int>(v);
}

const Json& JsonFields::member(const Json& obj, const std::string& key,
                               const std::string& field) const {
    const Json* j = find(obj, key);
    if (!j) fail(field, "missing");
    return *j;
}

const Json* JsonFields::find(const Json& obj, const std::string& key) {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
}

std::string JsonFields::type_name(const Json& j) {
    if (j.is_null()) return "null";
    if (j.is_boolean()) return "a boolean";
    if (j.is_string()) return "a string";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "a number";
}

const Json& JsonFields::object(const Json& j, const std::string& field,
                               const std::string& what) const {
    if (!j.is_object()) fail(field, "expected " + what + ", got " + type_name(j));
    return j;
}

const Json& JsonFields::array(const Json& j, const std::string& field) const {
    if (!j.is_array()) fail(field, "expected an array, got " + type_name(j));
    return j;
}

std::string JsonFields::string(const Json& j, const std::string& field,
                               const std::string& what) const {
    if (!j.is_string()) fail(field, "expected " + what + ", got " + type_name(j));
    return j.get<std::string>();
}

double JsonFields::number(const Json& j, const std::string& field) const {
    if (!j.is_number()) fail(field, "expected a number, got " + type_name(j));
    double x = j.get<double>();
    if (!std::isfinite(x)) fail(field, "not a finite number");
    return x;
}

double JsonFields::number(const Json& j, const std::string& field, double lo, double hi) const {
    const double x = number(j, field);
    if (x < lo || x > hi) {
        std::ostringstream os;
        os << "value " << x << " out of range " << lo << ".." << hi;
        fail(field, os.str());
    }
    return x;
}

long long JsonFields::integer(const Json& j, const std::string& field, long long lo,
                              long long hi) const {
    if (!j.is_number()) fail(field, "expected an integer, got " + type_name(j));
    double x = j.get<double>();
    if (j.is_number_float() && (!std::isfinite(x) || x != std::floor(x)))
        fail(field, "expected an integer");
    if (j.is_number_unsigned() ? j.get<unsigned long long>() > static_cast<unsigned long long>(hi)
                               : (x < static_cast<double>(lo) || x > static_cast<double>(hi)))
        fail(field, "value " + j.dump() + " out of range " + range_text(lo, hi));
    long long v = j.is_number_float() ? static_cast<long long>(x) : j.get<long long>();
    if (v < lo || v > hi)
        fail(field, "value " + std::to_string(v) + " out of range " + range_text(lo, hi));
    return v;
}

Vec3 JsonFields::vec3(const Json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 3) fail(field, "expected [x, y, z]");
    return {number(j[0], element_field(field, 0)), number(j[1], element_field(field, 1)),
            number(j[2], element_field(field, 2))};
}

Vec3 JsonFields::uv(const Json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 2) fail(field, "expected [u, v]");
    return {number(j[0], element_field(field, 0)), number(j[1], element_field(field, 1)), 0};
}

std::vector<double> JsonFields::numbers(const Json& j, const std::string& field) const {
    array(j, field);
    std::vector<double> out;
    out.reserve(j.size()); // bounded by the file's own size
    for (size_t k = 0; k < j.size(); ++k) out.push_back(number(j[k], element_field(field, k)));
    return out;
}

double JsonFields::number_or(const Json& obj, const std::string& parent, const std::string& key,
                             double fallback, double lo, double hi) const {
    const Json* j = find(obj, key);
    return j ? number(*j, member_field(parent, key), lo, hi) : fallback;
}

long long JsonFields::integer_or(const Json& obj, const std::string& parent, const std::string& key,
                                 long long fallback, long long lo, long long hi) const {
    const Json* j = find(obj, key);
    return j ? integer(*j, member_field(parent, key), lo, hi) : fallback;
}

} // namespace seamless
