// SPDX-License-Identifier: MIT
#include <seamless/model/brep_json.h>

#include <algorithm>
#include <climits>

namespace seamless {
namespace {

// Reads one B-rep: every count is checked against the limits before the
// reader reserves for it, and every index is read as 0..max_brep_items-1
// (validate_brep checks it against its list afterwards).
class BRepReader {
  public:
    BRepReader(const JsonFields& r, const ModelLimits& limits) : r_(r), limits_(limits) {}

    // The array member `key` of obj, at most `limit` elements long.
    const Json& list(const Json& obj, const std::string& parent, const char* key, long long limit,
                     const char* what) const {
        const std::string f = member_field(parent, key);
        const Json& j = r_.array(r_.member(obj, key, f), f);
        check_limit(f, static_cast<long long>(j.size()), limit, what);
        return j;
    }
    // As list(), an empty array when absent.
    const Json& list_or_empty(const Json& obj, const std::string& parent, const char* key,
                              const char* what) const {
        static const Json empty = Json::array();
        return JsonFields::find(obj, key) ? list(obj, parent, key, limits_.max_brep_items, what)
                                          : empty;
    }
    void check_limit(const std::string& f, long long n, long long limit, const char* what) const {
        if (n > limit)
            r_.fail(f, std::to_string(n) + " " + what + " exceed the limit of " +
                           std::to_string(limit));
    }
    int index(const Json& j, const std::string& f) const {
        const long long last = std::min<long long>(limits_.max_brep_items, INT_MAX) - 1;
        return static_cast<int>(r_.integer(j, f, 0, last)); // BRep's indices are ints
    }
    std::vector<int> indices(const Json& obj, const std::string& parent, const char* key,
                             const char* what) const {
        const Json& j = list(obj, parent, key, limits_.max_brep_items, what);
        const std::string f = member_field(parent, key);
        std::vector<int> out;
        out.reserve(j.size());
        for (size_t k = 0; k < j.size(); ++k) out.push_back(index(j[k], element_field(f, k)));
        return out;
    }
    bool flag_or(const Json& obj, const std::string& parent, const char* key) const {
        const Json* j = JsonFields::find(obj, key);
        if (!j) return false;
        if (!j->is_boolean())
            r_.fail(member_field(parent, key),
                    "expected true or false, got " + JsonFields::type_name(*j));
        return j->get<bool>();
    }
    std::string name_or(const Json& obj, const std::string& parent, std::string fallback) const {
        const Json* j = JsonFields::find(obj, "name");
        return j ? r_.string(*j, member_field(parent, "name")) : fallback;
    }

    BSplineCurve curve(const Json& js, const std::string& f, bool pcurve) const {
        r_.object(js, f);
        BSplineCurve c;
        c.degree = static_cast<int>(
            r_.integer(r_.member(js, "degree", f + ".degree"), f + ".degree", 1, kMaxDegree));
        const std::string fp = f + ".points";
        const Json& jp = list(js, f, "points", limits_.max_curve_points, "control points");
        c.points.reserve(jp.size());
        for (size_t i = 0; i < jp.size(); ++i)
            c.points.push_back(pcurve ? r_.uv(jp[i], element_field(fp, i))
                                      : r_.vec3(jp[i], element_field(fp, i)));
        const std::string fk = f + ".knots";
        const Json& jk = r_.array(r_.member(js, "knots", fk), fk);
        count(jk, fk, jp.size() + c.degree + 1);
        c.knots = r_.numbers(jk, fk);
        if (const Json* w = JsonFields::find(js, "weights")) {
            count(r_.array(*w, f + ".weights"), f + ".weights", jp.size());
            c.weights = r_.numbers(*w, f + ".weights");
        }
        return c;
    }

    BRepEdge edge(const Json& js, const std::string& f) const {
        r_.object(js, f);
        BRepEdge e;
        const Json& c = r_.member(js, "curve", f + ".curve");
        e.curve = c.is_null() ? -1 : index(c, f + ".curve");
        const Json& range = r_.array(r_.member(js, "range", f + ".range"), f + ".range");
        if (range.size() != 2) r_.fail(f + ".range", "expected [t0, t1]");
        e.t0 = r_.number(range[0], f + ".range[0]");
        e.t1 = r_.number(range[1], f + ".range[1]");
        const Json& v = r_.array(r_.member(js, "vertices", f + ".vertices"), f + ".vertices");
        if (v.size() != 2) r_.fail(f + ".vertices", "expected [start, end]");
        e.start = index(v[0], f + ".vertices[0]");
        e.end = index(v[1], f + ".vertices[1]");
        e.tolerance = tolerance_or_zero(js, f);
        return e;
    }

    BRepFace face(const Json& js, const std::string& f, size_t k, long long& coedges) const {
        r_.object(js, f);
        BRepFace face;
        face.surface = index(r_.member(js, "surface", f + ".surface"), f + ".surface");
        face.reversed = flag_or(js, f, "reversed");
        face.name = name_or(js, f, "face-" + std::to_string(k));
        const Json& loops = list(js, f, "loops", limits_.max_brep_items, "loops");
        face.loops.resize(loops.size());
        for (size_t l = 0; l < loops.size(); ++l) {
            const std::string fl = element_field(f + ".loops", l);
            const Json& jc =
                list(r_.object(loops[l], fl), fl, "coedges", limits_.max_brep_items, "coedges");
            coedges += static_cast<long long>(jc.size());
            check_limit(fl + ".coedges", coedges, limits_.max_brep_items, "coedges in all");
            std::vector<BRepCoedge>& out = face.loops[l].coedges;
            out.reserve(jc.size());
            for (size_t c = 0; c < jc.size(); ++c) {
                const std::string fc = element_field(fl + ".coedges", c);
                const Json& j = r_.object(jc[c], fc);
                BRepCoedge ce;
                ce.edge = index(r_.member(j, "edge", fc + ".edge"), fc + ".edge");
                ce.reversed = flag_or(j, fc, "reversed");
                ce.pcurve = index(r_.member(j, "pcurve", fc + ".pcurve"), fc + ".pcurve");
                out.push_back(ce);
            }
        }
        return face;
    }

    double tolerance_or_zero(const Json& js, const std::string& f) const {
        const Json* t = JsonFields::find(js, "tolerance");
        return t ? r_.number(*t, f + ".tolerance") : 0.0;
    }

  private:
    void count(const Json& j, const std::string& f, size_t n) const {
        if (j.size() != n)
            r_.fail(f,
                    "expected " + std::to_string(n) + " numbers, got " + std::to_string(j.size()));
    }
    const JsonFields& r_;
    const ModelLimits& limits_;
};

// Each element of the list `key` of j through read(element, field, index).
template <class T, class Read>
void read_list(const Json& list, const char* key, std::vector<T>& out, Read read) {
    out.reserve(list.size());
    for (size_t k = 0; k < list.size(); ++k)
        out.push_back(read(list[k], element_field(std::string("brep.") + key, k), k));
}

} // namespace

void read_brep_json(const JsonFields& r, const Json& j, const ModelLimits& limits, BRep& b) {
    const BRepReader in(r, limits);
    const std::string f = "brep";
    r.object(j, f);
    const long long n = limits.max_brep_items;
    read_list(in.list(j, f, "vertices", n, "vertices"), "vertices", b.vertices,
              [&](const Json& js, const std::string& fv, size_t) {
                  r.object(js, fv);
                  return BRepVertex{r.vec3(r.member(js, "point", fv + ".point"), fv + ".point"),
                                    in.tolerance_or_zero(js, fv)};
              });
    read_list(
        in.list(j, f, "curves", n, "curves"), "curves", b.curves,
        [&](const Json& js, const std::string& fc, size_t) { return in.curve(js, fc, false); });
    read_list(
        in.list(j, f, "pcurves", n, "pcurves"), "pcurves", b.pcurves,
        [&](const Json& js, const std::string& fc, size_t) { return in.curve(js, fc, true); });
    read_list(in.list(j, f, "edges", n, "edges"), "edges", b.edges,
              [&](const Json& js, const std::string& fe, size_t) { return in.edge(js, fe); });
    long long coedges = 0;
    read_list(in.list(j, f, "faces", n, "faces"), "faces", b.faces,
              [&](const Json& js, const std::string& ff, size_t k) {
                  return in.face(js, ff, k, coedges);
              });
    read_list(
        in.list_or_empty(j, f, "shells", "shells"), "shells", b.shells,
        [&](const Json& js, const std::string& fs, size_t) {
            r.object(js, fs);
            return BRepShell{in.indices(js, fs, "faces", "faces"), in.flag_or(js, fs, "closed")};
        });
    read_list(in.list_or_empty(j, f, "solids", "solids"), "solids", b.solids,
              [&](const Json& js, const std::string& fs, size_t k) {
                  r.object(js, fs);
                  return BRepSolid{in.indices(js, fs, "shells", "shells"),
                                   in.name_or(js, fs, "solid-" + std::to_string(k))};
              });
}

namespace {

void write_numbers(std::ostream& os, const std::vector<double>& v) {
    os << '[';
    for (size_t i = 0; i < v.size(); ++i) {
        if (i) os << ", ";
        write_json_number(os, v[i]);
    }
    os << ']';
}

// [x, y, z], or [u, v] for a pcurve's point.
void write_point(std::ostream& os, const Vec3& p, int dims) {
    os << '[';
    for (int i = 0; i < dims; ++i) {
        if (i) os << ", ";
        write_json_number(os, p[i]);
    }
    os << ']';
}

void write_curve(std::ostream& os, const BSplineCurve& c, int dims) {
    os << "{\"degree\": " << c.degree << ", \"knots\": ";
    write_numbers(os, c.knots);
    os << ",\n    \"points\": [";
    for (size_t i = 0; i < c.points.size(); ++i) {
        if (i) os << ", ";
        write_point(os, c.points[i], dims);
    }
    os << ']';
    if (c.rational()) {
        os << ",\n    \"weights\": ";
        write_numbers(os, c.weights);
    }
    os << '}';
}

void write_edge(std::ostream& os, const BRepEdge& e) {
    os << "{\"curve\": ";
    if (e.degenerate())
        os << "null";
    else
        os << e.curve;
    os << ", \"range\": ";
    write_numbers(os, {e.t0, e.t1});
    os << ", \"vertices\": [" << e.start << ", " << e.end << "], \"tolerance\": ";
    write_json_number(os, e.tolerance);
    os << '}';
}

const char* boolean(bool b) {
    return b ? "true" : "false";
}

void write_face(std::ostream& os, const BRepFace& f) {
    os << "{\"surface\": " << f.surface << ", \"reversed\": " << boolean(f.reversed)
       << ", \"name\": ";
    write_json_string(os, f.name);
    os << ", \"loops\": [";
    for (size_t l = 0; l < f.loops.size(); ++l) {
        os << (l ? ",\n" : "\n") << "    {\"coedges\": [";
        const std::vector<BRepCoedge>& ce = f.loops[l].coedges;
        for (size_t c = 0; c < ce.size(); ++c)
            os << (c ? ",\n     " : "") << "{\"edge\": " << ce[c].edge
               << ", \"reversed\": " << boolean(ce[c].reversed) << ", \"pcurve\": " << ce[c].pcurve
               << '}';
        os << "]}";
    }
    os << "]}";
}

// "key": [ one element a line ], closed by `tail`.
template <class T, class Write>
void write_list(std::ostream& os, const char* key, const std::vector<T>& v, const char* tail,
                Write write) {
    os << "  \"" << key << "\": [";
    for (size_t k = 0; k < v.size(); ++k) {
        os << (k ? ",\n   " : "\n   ");
        write(v[k]);
    }
    os << (v.empty() ? "]" : "\n  ]") << tail;
}

} // namespace

void write_brep_json(std::ostream& os, const BRep& b) {
    os << "{\n";
    write_list(os, "vertices", b.vertices, ",\n", [&](const BRepVertex& v) {
        os << "{\"point\": ";
        write_point(os, v.point, 3);
        os << ", \"tolerance\": ";
        write_json_number(os, v.tolerance);
        os << '}';
    });
    write_list(os, "curves", b.curves, ",\n",
               [&](const BSplineCurve& c) { write_curve(os, c, 3); });
    write_list(os, "pcurves", b.pcurves, ",\n",
               [&](const BSplineCurve& c) { write_curve(os, c, 2); });
    write_list(os, "edges", b.edges, ",\n", [&](const BRepEdge& e) { write_edge(os, e); });
    write_list(os, "faces", b.faces, ",\n", [&](const BRepFace& f) { write_face(os, f); });
    write_list(os, "shells", b.shells, ",\n", [&](const BRepShell& s) {
        os << "{\"faces\": ";
        write_json_ints(os, s.faces);
        os << ", \"closed\": " << boolean(s.closed) << '}';
    });
    write_list(os, "solids", b.solids, "\n", [&](const BRepSolid& s) {
        os << "{\"shells\": ";
        write_json_ints(os, s.shells);
        os << ", \"name\": ";
        write_json_string(os, s.name);
        os << '}';
    });
    os << " }";
}

} // namespace seamless
