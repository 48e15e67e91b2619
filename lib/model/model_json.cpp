// SPDX-License-Identifier: MIT
// Reader of the version-1 JSON model format (docs/formats.md).
#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <nlohmann/json.hpp>

#include <cmath>

namespace seamless {
namespace {

using json = nlohmann::json;

struct Reader {
    const std::string& file;

    [[noreturn]] void fail(const std::string& field, const std::string& msg) const {
        throw InputError(file, field, msg);
    }
    static std::string type_name(const json& j) {
        if (j.is_null()) return "null";
        if (j.is_boolean()) return "a boolean";
        if (j.is_string()) return "a string";
        if (j.is_array()) return "an array";
        if (j.is_object()) return "an object";
        return "a number";
    }
    const json& member(const json& obj, const std::string& key, const std::string& field) const {
        auto it = obj.find(key);
        if (it == obj.end()) fail(field, "missing");
        return *it;
    }
    double number(const json& j, const std::string& field) const {
        if (!j.is_number()) fail(field, "expected a number, got " + type_name(j));
        double x = j.get<double>();
        if (!std::isfinite(x)) fail(field, "not a finite number");
        return x;
    }
    // An integer in [lo, hi]; 4.0 counts as 4.
    long long integer(const json& j, const std::string& field, long long lo, long long hi) const {
        if (!j.is_number()) fail(field, "expected an integer, got " + type_name(j));
        double x = j.get<double>();
        if (j.is_number_float() && (!std::isfinite(x) || x != std::floor(x)))
            fail(field, "expected an integer");
        if (j.is_number_unsigned() ? j.get<unsigned long long>() > static_cast<unsigned long long>(hi)
                                   : (x < static_cast<double>(lo) || x > static_cast<double>(hi)))
            fail(field, "value " + j.dump() + " out of range " + std::to_string(lo) + ".." +
                            std::to_string(hi));
        long long v = j.is_number_float() ? static_cast<long long>(x) : j.get<long long>();
        if (v < lo || v > hi)
            fail(field, "value " + std::to_string(v) + " out of range " + std::to_string(lo) + ".." +
                            std::to_string(hi));
        return v;
    }
    const json& array(const json& j, const std::string& field) const {
        if (!j.is_array()) fail(field, "expected an array, got " + type_name(j));
        return j;
    }
    std::vector<double> numbers(const json& j, const std::string& field) const {
        array(j, field);
        std::vector<double> out;
        out.reserve(j.size()); // bounded by the file's own size
        for (size_t k = 0; k < j.size(); ++k)
            out.push_back(number(j[k], field + "[" + std::to_string(k) + "]"));
        return out;
    }
};

// SAX handler that only tracks where in the document the parser is, so that an
// error nlohmann reports without a field (a number like 1e999 that overflows to
// infinity) can still be named: "surfaces[0].knots_u[3]".
class PathTracker : public nlohmann::json_sax<json> {
  public:
    std::string path() const {
        std::string s;
        for (const Frame& f : stack_) {
            if (f.array) s += "[" + std::to_string(f.index) + "]";
            else if (!f.key.empty()) s += (s.empty() ? "" : ".") + f.key;
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

} // namespace

Model parse_model_json(const std::string& text, const std::string& file, const ModelLimits& limits) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        // e.byte is the 1-based offset; report line and column, as an editor shows them.
        size_t byte = e.byte == 0 ? 0 : e.byte - 1, line = 1, col = 1;
        for (size_t k = 0; k < byte && k < text.size(); ++k) {
            if (text[k] == '\n') ++line, col = 1;
            else ++col;
        }
        std::string what = e.what();
        auto pos = what.find("syntax error");
        throw InputError(file, "line " + std::to_string(line) + ", column " + std::to_string(col),
                         "JSON " + (pos == std::string::npos ? what : what.substr(pos)));
    } catch (const json::out_of_range&) {
        // JSON has no NaN or infinity, but 1e999 overflows to infinity.
        PathTracker where;
        json::sax_parse(text, &where);
        throw InputError(file, where.path(), "not a finite number (overflows a double)");
    }
    Reader r{file};
    if (!root.is_object()) r.fail("", "expected a JSON object at the top level");
    const json& version = r.member(root, "version", "version");
    if (r.integer(version, "version", 0, 1'000'000) != 1)
        r.fail("version", "unsupported version " + version.dump() + " (this reader knows 1)");
    const json& surfaces = r.array(r.member(root, "surfaces", "surfaces"), "surfaces");
    if (surfaces.empty()) r.fail("surfaces", "expected at least one surface");
    if (static_cast<long long>(surfaces.size()) > limits.max_surfaces)
        r.fail("surfaces", std::to_string(surfaces.size()) + " surfaces exceed the limit of " +
                               std::to_string(limits.max_surfaces));

    Model m;
    m.source = file;
    m.surfaces.reserve(surfaces.size());
    for (size_t k = 0; k < surfaces.size(); ++k) {
        const std::string f = "surfaces[" + std::to_string(k) + "]";
        const json& js = surfaces[k];
        if (!js.is_object()) r.fail(f, "expected an object, got " + Reader::type_name(js));
        BSplineSurface s;
        s.name = "surface-" + std::to_string(k);
        if (auto it = js.find("name"); it != js.end()) {
            if (!it->is_string()) r.fail(f + ".name", "expected a string, got " + Reader::type_name(*it));
            s.name = it->get<std::string>();
        }
        const json& deg = r.array(r.member(js, "degree", f + ".degree"), f + ".degree");
        if (deg.size() != 2) r.fail(f + ".degree", "expected [p, q], got " + std::to_string(deg.size()) + " numbers");
        s.degree_u = static_cast<int>(r.integer(deg[0], f + ".degree[0]", 1, kMaxDegree));
        s.degree_v = static_cast<int>(r.integer(deg[1], f + ".degree[1]", 1, kMaxDegree));
        const json& size = r.array(r.member(js, "size", f + ".size"), f + ".size");
        if (size.size() != 2) r.fail(f + ".size", "expected [nu, nv], got " + std::to_string(size.size()) + " numbers");
        const long long nu = r.integer(size[0], f + ".size[0]", 1, limits.max_control_points);
        const long long nv = r.integer(size[1], f + ".size[1]", 1, limits.max_control_points);
        if (nu * nv > limits.max_control_points)
            r.fail(f + ".size", std::to_string(nu) + " x " + std::to_string(nv) +
                                    " control points exceed the limit of " +
                                    std::to_string(limits.max_control_points));
        s.size_u = static_cast<int>(nu);
        s.size_v = static_cast<int>(nv);
        if (s.size_u < s.degree_u + 1 || s.size_v < s.degree_v + 1)
            r.fail(f + ".size", "control net " + std::to_string(nu) + " x " + std::to_string(nv) +
                                    " too small for degree [" + std::to_string(s.degree_u) + ", " +
                                    std::to_string(s.degree_v) + "] (need degree+1 points per direction)");
        const std::string fu = f + ".knots_u", fv = f + ".knots_v";
        const json& ju = r.array(r.member(js, "knots_u", fu), fu);
        if (ju.size() != static_cast<size_t>(nu + s.degree_u + 1))
            r.fail(fu, "expected " + std::to_string(nu + s.degree_u + 1) + " numbers, got " + std::to_string(ju.size()));
        s.knots_u = r.numbers(ju, fu);
        const json& jv = r.array(r.member(js, "knots_v", fv), fv);
        if (jv.size() != static_cast<size_t>(nv + s.degree_v + 1))
            r.fail(fv, "expected " + std::to_string(nv + s.degree_v + 1) + " numbers, got " + std::to_string(jv.size()));
        s.knots_v = r.numbers(jv, fv);

        const std::string fc = f + ".control_points";
        const json& jc = r.array(r.member(js, "control_points", fc), fc);
        if (jc.size() != static_cast<size_t>(nu * nv))
            r.fail(fc, "expected " + std::to_string(nu * nv) + " points, got " + std::to_string(jc.size()));
        s.points.reserve(jc.size());
        for (size_t i = 0; i < jc.size(); ++i) {
            const std::string fi = fc + "[" + std::to_string(i) + "]";
            const json& pt = jc[i];
            if (!pt.is_array() || pt.size() != 3) r.fail(fi, "expected [x, y, z]");
            s.points.push_back({r.number(pt[0], fi + "[0]"), r.number(pt[1], fi + "[1]"),
                                r.number(pt[2], fi + "[2]")});
        }
        if (auto it = js.find("weights"); it != js.end()) {
            const std::string fw = f + ".weights";
            r.array(*it, fw);
            if (it->size() != static_cast<size_t>(nu * nv))
                r.fail(fw, "expected " + std::to_string(nu * nv) + " numbers, got " + std::to_string(it->size()));
            s.weights = r.numbers(*it, fw);
        }
        validate_surface(s, file, f);
        m.surfaces.push_back(std::move(s));
    }
    return m;
}

} // namespace seamless
