// SPDX-License-Identifier: MIT
// Reader and writer of the JSON model format (docs/formats.md): version 1,
// surfaces; version 2, surfaces and a B-rep (brep_json.cpp).
#include <seamless/model/brep_json.h>
#include <seamless/model/json_fields.h>
#include <seamless/model/model.h>

#include <sstream>

namespace seamless {
namespace {

// "expected 6 numbers, got 5" unless the array j has n elements.
void check_count(const JsonFields& r, const Json& j, const std::string& field, long long n,
                 const char* what) {
    if (j.size() != static_cast<size_t>(n))
        r.fail(field,
               "expected " + std::to_string(n) + " " + what + ", got " + std::to_string(j.size()));
}

// A pair [a, b] (degrees, sizes): its array, after its name `pair` is checked.
const Json& pair_of(const JsonFields& r, const Json& js, const std::string& f, const char* key,
                    const char* pair) {
    const std::string field = member_field(f, key);
    const Json& j = r.array(r.member(js, key, field), field);
    if (j.size() != 2)
        r.fail(field,
               std::string("expected ") + pair + ", got " + std::to_string(j.size()) + " numbers");
    return j;
}

// The degrees and the size of the control net of surface f.
void read_shape(const JsonFields& r, const Json& js, const std::string& f,
                const ModelLimits& limits, BSplineSurface& s) {
    const Json& deg = pair_of(r, js, f, "degree", "[p, q]");
    s.degree_u = static_cast<int>(r.integer(deg[0], f + ".degree[0]", 1, kMaxDegree));
    s.degree_v = static_cast<int>(r.integer(deg[1], f + ".degree[1]", 1, kMaxDegree));
    const Json& size = pair_of(r, js, f, "size", "[nu, nv]");
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
                                std::to_string(s.degree_v) +
                                "] (need degree+1 points per direction)");
}

// Knots, control points and weights of surface f, whose shape is read.
void read_net(const JsonFields& r, const Json& js, const std::string& f, BSplineSurface& s) {
    const long long nu = s.size_u, nv = s.size_v;
    const std::string fu = f + ".knots_u", fv = f + ".knots_v";
    const Json& ju = r.array(r.member(js, "knots_u", fu), fu);
    check_count(r, ju, fu, nu + s.degree_u + 1, "numbers");
    s.knots_u = r.numbers(ju, fu);
    const Json& jv = r.array(r.member(js, "knots_v", fv), fv);
    check_count(r, jv, fv, nv + s.degree_v + 1, "numbers");
    s.knots_v = r.numbers(jv, fv);

    const std::string fc = f + ".control_points";
    const Json& jc = r.array(r.member(js, "control_points", fc), fc);
    check_count(r, jc, fc, nu * nv, "points");
    s.points.reserve(jc.size());
    for (size_t i = 0; i < jc.size(); ++i) s.points.push_back(r.vec3(jc[i], element_field(fc, i)));
    if (const Json* w = JsonFields::find(js, "weights")) {
        const std::string fw = f + ".weights";
        r.array(*w, fw);
        check_count(r, *w, fw, nu * nv, "numbers");
        s.weights = r.numbers(*w, fw);
    }
}

} // namespace

Model parse_model_json(const std::string& text, const std::string& file,
                       const ModelLimits& limits) {
    const JsonFields r(file);
    const Json root = r.parse_object(text);
    const int version = r.check_version(root, 2);
    const Json& surfaces = r.array(r.member(root, "surfaces", "surfaces"), "surfaces");
    if (surfaces.empty()) r.fail("surfaces", "expected at least one surface");
    if (static_cast<long long>(surfaces.size()) > limits.max_surfaces)
        r.fail("surfaces", std::to_string(surfaces.size()) + " surfaces exceed the limit of " +
                               std::to_string(limits.max_surfaces));

    Model m;
    m.source = file;
    m.surfaces.reserve(surfaces.size());
    for (size_t k = 0; k < surfaces.size(); ++k) {
        const std::string f = element_field("surfaces", k);
        const Json& js = r.object(surfaces[k], f);
        BSplineSurface s;
        s.name = "surface-" + std::to_string(k);
        if (const Json* name = JsonFields::find(js, "name")) s.name = r.string(*name, f + ".name");
        read_shape(r, js, f, limits, s);
        read_net(r, js, f, s);
        validate_surface(s, file, f);
        m.surfaces.push_back(std::move(s));
    }
    const Json* brep = JsonFields::find(root, "brep");
    if (version == 1) {
        // Ignoring it, as other unknown members are, would drop the trims.
        if (brep) r.fail("brep", "a B-rep needs \"version\": 2");
        if (JsonFields::find(root, "assembly"))
            r.fail("assembly", "an assembly needs \"version\": 2");
        return m;
    }
    if (!brep) r.fail("brep", "missing (version 2 is surfaces and a B-rep)");
    read_brep_json(r, *brep, limits, m.brep);
    if (m.brep.empty()) r.fail("brep.faces", "expected at least one face");
    validate_brep(m, file, limits);
    if (const Json* assembly = JsonFields::find(root, "assembly")) {
        read_assembly_json(r, *assembly, limits, m.assembly);
        validate_assembly(m, file);
    }
    return m;
}

std::string to_json(const Model& m) {
    std::ostringstream os;
    os << "{\"version\": " << (m.brep.empty() ? 1 : 2) << ",\n \"surfaces\": [";
    for (size_t k = 0; k < m.surfaces.size(); ++k) {
        const BSplineSurface& s = m.surfaces[k];
        auto list = [&](const std::vector<double>& v) {
            os << '[';
            for (size_t i = 0; i < v.size(); ++i) {
                if (i) os << ", ";
                write_json_number(os, v[i]);
            }
            os << ']';
        };
        os << (k ? ",\n" : "\n") << "  {\"name\": ";
        write_json_string(os, s.name);
        os << ", \"degree\": [" << s.degree_u << ", " << s.degree_v << "], \"size\": [" << s.size_u
           << ", " << s.size_v << "],\n";
        os << "   \"knots_u\": ";
        list(s.knots_u);
        os << ",\n   \"knots_v\": ";
        list(s.knots_v);
        os << ",\n   \"control_points\": [";
        for (size_t i = 0; i < s.points.size(); ++i) {
            os << (i ? ", " : "");
            list({s.points[i].x, s.points[i].y, s.points[i].z});
        }
        os << ']';
        if (s.rational()) {
            os << ",\n   \"weights\": ";
            list(s.weights);
        }
        os << '}';
    }
    os << "\n ]";
    if (!m.brep.empty()) {
        os << ",\n \"brep\": ";
        write_brep_json(os, m.brep);
        if (!m.assembly.empty()) {
            os << ",\n \"assembly\": ";
            write_assembly_json(os, m.assembly);
        }
    }
    os << "}\n";
    return os.str();
}

} // namespace seamless
