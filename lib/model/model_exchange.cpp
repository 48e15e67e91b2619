// SPDX-License-Identifier: MIT
// The binary form of a Model between the STEP/IGES reader's process and the
// library (model_exchange.h). Layout: the tag, then the members in the order
// of their declaration; a list is its count (8 bytes) and its elements; a
// string is its length and its bytes; int is 4 bytes, bool 1, double its 8
// bytes of IEEE 754.
#include <seamless/model/model_exchange.h>

#include <seamless/base/error.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace seamless {
namespace {

constexpr std::string_view kTag = "seamless-model-exchange 2\n";

// A member added to one of these types must be written and read below; the
// sizes (x86-64, libstdc++) stop the build until it is.
static_assert(sizeof(Model) == 416 && sizeof(BRep) == 168 && sizeof(Assembly) == 144 &&
                  sizeof(AssemblyPart) == 48 && sizeof(AssemblyNode) == 144 && sizeof(Rgba) == 32 &&
                  sizeof(AssemblyLayer) == 112 && sizeof(SurfaceOrigin) == 80 &&
                  sizeof(BSplineSurface) == 144 && sizeof(BSplineCurve) == 80 &&
                  sizeof(BRepFace) == 64 && sizeof(BRepEdge) == 40 && sizeof(BRepSolid) == 56 &&
                  sizeof(BRepShell) == 32 && sizeof(BRepCoedge) == 12 && sizeof(BRepVertex) == 32,
              "a member was added to Model or its parts: write and read it in model_exchange.cpp");

static_assert(sizeof(Vec3) == 3 * sizeof(double), "points are written as their doubles");

class Writer {
  public:
    std::string out;

    template <class T> void scalar(T x) {
        static_assert(std::is_arithmetic_v<T>);
        out.append(reinterpret_cast<const char*>(&x), sizeof x);
    }
    void count(std::size_t n) { scalar<std::uint64_t>(n); }
    void string(const std::string& s) {
        count(s.size());
        out += s;
    }
    void doubles(const std::vector<double>& v) {
        count(v.size());
        if (!v.empty())
            out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
    }
    void points(const std::vector<Vec3>& v) {
        count(v.size());
        if (!v.empty())
            out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(Vec3));
    }
    void ints(const std::vector<int>& v) {
        count(v.size());
        for (int i : v) scalar<std::int32_t>(i);
    }
    template <class T, class Each> void list(const std::vector<T>& v, Each each) {
        count(v.size());
        for (const T& x : v) each(x);
    }

    void surface(const BSplineSurface& s) {
        string(s.name);
        for (int i : {s.degree_u, s.degree_v, s.size_u, s.size_v}) scalar<std::int32_t>(i);
        doubles(s.knots_u);
        doubles(s.knots_v);
        points(s.points);
        doubles(s.weights);
    }
    void curve(const BSplineCurve& c) {
        scalar<std::int32_t>(c.degree);
        doubles(c.knots);
        points(c.points);
        doubles(c.weights);
    }
    void brep(const BRep& b);
    void assembly(const Assembly& a);
};

void Writer::assembly(const Assembly& a) {
    list(a.parts, [&](const AssemblyPart& p) {
        string(p.name);
        for (int i : {p.face_count, p.shell_count, p.solid_count, p.colour})
            scalar<std::int32_t>(i);
    });
    list(a.nodes, [&](const AssemblyNode& n) {
        string(n.name);
        scalar<std::int32_t>(n.parent);
        for (double x : n.placement.m) scalar(x);
        scalar<std::int32_t>(n.part);
    });
    list(a.colours, [&](const Rgba& c) { scalar(c.r), scalar(c.g), scalar(c.b), scalar(c.a); });
    ints(a.solid_colours);
    ints(a.face_colours);
    list(a.layers, [&](const AssemblyLayer& l) {
        string(l.name);
        scalar<std::uint8_t>(l.visible);
        ints(l.parts);
        ints(l.solids);
        ints(l.faces);
    });
}

void Writer::brep(const BRep& b) {
    list(b.vertices, [&](const BRepVertex& v) {
        scalar(v.point.x), scalar(v.point.y), scalar(v.point.z), scalar(v.tolerance);
    });
    list(b.curves, [&](const BSplineCurve& c) { curve(c); });
    list(b.pcurves, [&](const BSplineCurve& c) { curve(c); });
    list(b.edges, [&](const BRepEdge& e) {
        for (int i : {e.curve, e.start, e.end}) scalar<std::int32_t>(i);
        scalar(e.t0), scalar(e.t1), scalar(e.tolerance);
    });
    list(b.faces, [&](const BRepFace& f) {
        scalar<std::int32_t>(f.surface);
        scalar<std::uint8_t>(f.reversed);
        string(f.name);
        list(f.loops, [&](const BRepLoop& l) {
            list(l.coedges, [&](const BRepCoedge& c) {
                scalar<std::int32_t>(c.edge);
                scalar<std::uint8_t>(c.reversed);
                scalar<std::int32_t>(c.pcurve);
            });
        });
    });
    list(b.shells, [&](const BRepShell& s) {
        ints(s.faces);
        scalar<std::uint8_t>(s.closed);
    });
    list(b.solids, [&](const BRepSolid& s) {
        ints(s.shells);
        string(s.name);
    });
}

// A field's name, built only on failure (reading costs no string per item):
// "brep.edges[3].curve" is {&{nullptr, "brep.edges", 3}, "curve"}.
struct Path {
    const Path* parent = nullptr;
    const char* name = "";
    long long index = -1;

    std::string str() const {
        std::string s = parent ? parent->str() : std::string();
        if (*name) s += (s.empty() ? "" : ".") + std::string(name);
        if (index >= 0) s += "[" + std::to_string(index) + "]";
        return s;
    }
};

class Reader {
  public:
    Reader(std::string_view bytes, const std::string& file, const ModelLimits& limits)
        : in_(bytes), file_(file), limits_(limits) {}

    [[noreturn]] void fail(const Path& field, const std::string& message) const {
        const std::string f = field.str();
        throw InputError(file_, "exchange" + (f.empty() ? "" : "." + f), message);
    }

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
    std::vector<double> doubles(const Path& field, long long limit) {
        std::vector<double> v(count(field, limit, sizeof(double)));
        if (!v.empty()) std::memcpy(v.data(), in_.data() + at_, v.size() * sizeof(double));
        at_ += v.size() * sizeof(double);
        return v;
    }
    Vec3 point(const Path& field) {
        const double x = scalar<double>(field), y = scalar<double>(field);
        return {x, y, scalar<double>(field)};
    }
    std::vector<Vec3> points(const Path& field, long long limit) {
        std::vector<Vec3> v(count(field, limit, 3 * sizeof(double)));
        if (!v.empty())
            std::memcpy(static_cast<void*>(v.data()), in_.data() + at_, v.size() * sizeof(Vec3));
        at_ += v.size() * sizeof(Vec3);
        return v;
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

    BSplineSurface surface(const Path& f);
    BSplineCurve curve(const Path& f);
    void brep(Model& m);
    void assembly(Assembly& a);

  private:
    std::string_view in_;
    std::size_t at_ = 0;
    const std::string& file_;
    const ModelLimits& limits_;
};

BSplineSurface Reader::surface(const Path& f) {
    BSplineSurface s;
    s.name = string({&f, "name"});
    s.degree_u = integer({&f, "degree"});
    s.degree_v = integer({&f, "degree"});
    s.size_u = integer({&f, "size"});
    s.size_v = integer({&f, "size"});
    const long long n = limits_.max_control_points;
    s.knots_u = doubles({&f, "knots_u"}, n + kMaxDegree + 1);
    s.knots_v = doubles({&f, "knots_v"}, n + kMaxDegree + 1);
    s.points = points({&f, "control_points"}, n);
    s.weights = doubles({&f, "weights"}, n);
    validate_surface(s, file_, "exchange." + f.str());
    return s;
}

BSplineCurve Reader::curve(const Path& f) {
    BSplineCurve c;
    c.degree = integer({&f, "degree"});
    const long long n = limits_.max_curve_points;
    c.knots = doubles({&f, "knots"}, n + kMaxDegree + 1);
    c.points = points({&f, "points"}, n);
    c.weights = doubles({&f, "weights"}, n);
    validate_curve(c, file_, "exchange." + f.str(), n);
    return c;
}

void Reader::brep(Model& m) {
    BRep& b = m.brep;
    b.vertices.resize(items({nullptr, "brep.vertices"}, 4 * sizeof(double)));
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
        const Path f{nullptr, "brep.vertices", static_cast<long long>(k)};
        b.vertices[k].point = point({&f, "point"});
        if (!is_finite(b.vertices[k].point)) fail({&f, "point"}, "not a finite point");
        b.vertices[k].tolerance = number({&f, "tolerance"});
    }
    b.curves.resize(items({nullptr, "brep.curves"}, 28));
    for (std::size_t k = 0; k < b.curves.size(); ++k)
        b.curves[k] = curve({nullptr, "brep.curves", static_cast<long long>(k)});
    b.pcurves.resize(items({nullptr, "brep.pcurves"}, 28));
    for (std::size_t k = 0; k < b.pcurves.size(); ++k)
        b.pcurves[k] = curve({nullptr, "brep.pcurves", static_cast<long long>(k)});
    b.edges.resize(items({nullptr, "brep.edges"}, 36));
    for (std::size_t k = 0; k < b.edges.size(); ++k) {
        const Path f{nullptr, "brep.edges", static_cast<long long>(k)};
        BRepEdge& e = b.edges[k];
        e.curve = index({&f, "curve"}, b.curves.size(), true);
        e.start = index({&f, "start"}, b.vertices.size());
        e.end = index({&f, "end"}, b.vertices.size());
        e.t0 = number({&f, "t0"});
        e.t1 = number({&f, "t1"});
        e.tolerance = number({&f, "tolerance"});
        if (!(e.t0 < e.t1)) fail(f, "empty parameter range");
    }
    b.faces.resize(items({nullptr, "brep.faces"}, 21));
    for (std::size_t k = 0; k < b.faces.size(); ++k) {
        const Path f{nullptr, "brep.faces", static_cast<long long>(k)};
        BRepFace& face = b.faces[k];
        face.surface = index({&f, "surface"}, m.surfaces.size());
        face.reversed = flag({&f, "reversed"});
        face.name = string({&f, "name"});
        face.loops.resize(items({&f, "loops"}, 8));
        for (std::size_t l = 0; l < face.loops.size(); ++l) {
            const Path fl{&f, "loops", static_cast<long long>(l)};
            std::vector<BRepCoedge>& coedges = face.loops[l].coedges;
            coedges.resize(items({&fl, "coedges"}, 9));
            for (std::size_t c = 0; c < coedges.size(); ++c) {
                const Path fc{&fl, "coedges", static_cast<long long>(c)};
                coedges[c].edge = index({&fc, "edge"}, b.edges.size());
                coedges[c].reversed = flag({&fc, "reversed"});
                coedges[c].pcurve = index({&fc, "pcurve"}, b.pcurves.size());
            }
        }
    }
    b.shells.resize(items({nullptr, "brep.shells"}, 9));
    for (std::size_t k = 0; k < b.shells.size(); ++k) {
        const Path f{nullptr, "brep.shells", static_cast<long long>(k)};
        b.shells[k].faces.resize(items({&f, "faces"}, 4));
        for (int& face : b.shells[k].faces) face = index({&f, "faces"}, b.faces.size());
        b.shells[k].closed = flag({&f, "closed"});
    }
    b.solids.resize(items({nullptr, "brep.solids"}, 16));
    for (std::size_t k = 0; k < b.solids.size(); ++k) {
        const Path f{nullptr, "brep.solids", static_cast<long long>(k)};
        b.solids[k].shells.resize(items({&f, "shells"}, 4));
        for (int& shell : b.solids[k].shells) shell = index({&f, "shells"}, b.shells.size());
        b.solids[k].name = string({&f, "name"});
    }
}

// The tree's indices and numbers are checked by validate_assembly after the
// whole model is read; here only what reading needs: counts within the bytes
// left, finite numbers.
void Reader::assembly(Assembly& a) {
    a.parts.resize(items({nullptr, "assembly.parts"}, 24));
    for (std::size_t k = 0; k < a.parts.size(); ++k) {
        const Path f{nullptr, "assembly.parts", static_cast<long long>(k)};
        AssemblyPart& p = a.parts[k];
        p.name = string({&f, "name"});
        p.face_count = integer({&f, "face_count"});
        p.shell_count = integer({&f, "shell_count"});
        p.solid_count = integer({&f, "solid_count"});
        p.colour = integer({&f, "colour"});
    }
    a.nodes.resize(items({nullptr, "assembly.nodes"}, 8 + 4 + 12 * sizeof(double) + 4));
    for (std::size_t k = 0; k < a.nodes.size(); ++k) {
        const Path f{nullptr, "assembly.nodes", static_cast<long long>(k)};
        AssemblyNode& n = a.nodes[k];
        n.name = string({&f, "name"});
        n.parent = integer({&f, "parent"});
        for (double& x : n.placement.m) x = number({&f, "placement"});
        n.part = integer({&f, "part"});
    }
    a.colours.resize(items({nullptr, "assembly.colours"}, 4 * sizeof(double)));
    for (std::size_t k = 0; k < a.colours.size(); ++k) {
        const Path f{nullptr, "assembly.colours", static_cast<long long>(k)};
        Rgba& c = a.colours[k];
        c.r = number(f), c.g = number(f), c.b = number(f), c.a = number(f);
    }
    for (auto [list, name] : {std::pair{&a.solid_colours, "assembly.solid_colours"},
                              std::pair{&a.face_colours, "assembly.face_colours"}}) {
        list->resize(items({nullptr, name}, 4));
        for (int& i : *list) i = integer({nullptr, name});
    }
    // A layer takes at least its name's length, its flag and 3 counts: 33 bytes.
    a.layers.resize(items({nullptr, "assembly.layers"}, 33));
    for (std::size_t k = 0; k < a.layers.size(); ++k) {
        const Path f{nullptr, "assembly.layers", static_cast<long long>(k)};
        AssemblyLayer& l = a.layers[k];
        l.name = string({&f, "name"});
        l.visible = flag({&f, "visible"});
        for (auto [list, name] : {std::pair{&l.parts, "parts"}, std::pair{&l.solids, "solids"},
                                  std::pair{&l.faces, "faces"}}) {
            list->resize(items({&f, name}, 4));
            for (int& i : *list) i = integer({&f, name});
        }
    }
}

} // namespace

std::string write_model_exchange(const Model& m) {
    Writer w;
    w.out = kTag;
    w.string(m.source);
    w.list(m.surfaces, [&](const BSplineSurface& s) { w.surface(s); });
    w.list(m.origins, [&](const SurfaceOrigin& o) {
        w.string(o.entity);
        w.string(o.kind);
        w.scalar<std::uint8_t>(o.exact);
        w.scalar(o.approximation_error);
    });
    w.list(m.warnings, [&](const std::string& s) { w.string(s); });
    w.brep(m.brep);
    w.assembly(m.assembly);
    return std::move(w.out);
}

Model read_model_exchange(std::string_view bytes, const std::string& file,
                          const ModelLimits& limits) {
    Reader r(bytes, file, limits);
    r.tag();
    Model m;
    m.source = r.string({nullptr, "source"});
    // A surface takes at least its name's length, 4 ints and 4 counts: 56 bytes.
    m.surfaces.resize(r.count({nullptr, "surfaces"}, limits.max_surfaces, 56));
    for (std::size_t k = 0; k < m.surfaces.size(); ++k)
        m.surfaces[k] = r.surface({nullptr, "surfaces", static_cast<long long>(k)});
    const std::size_t origins = r.count({nullptr, "origins"}, limits.max_surfaces, 25);
    if (origins != 0 && origins != m.surfaces.size())
        r.fail({nullptr, "origins"}, std::to_string(origins) + " origins for " +
                                         std::to_string(m.surfaces.size()) + " surfaces");
    m.origins.resize(origins);
    for (std::size_t k = 0; k < origins; ++k) {
        const Path f{nullptr, "origins", static_cast<long long>(k)};
        SurfaceOrigin& o = m.origins[k];
        o.entity = r.string({&f, "entity"});
        o.kind = r.string({&f, "kind"});
        o.exact = r.flag({&f, "exact"});
        o.approximation_error = r.scalar<double>({&f, "approximation_error"});
    }
    m.warnings.resize(r.count({nullptr, "warnings"}, limits.max_surfaces, 8));
    for (std::size_t k = 0; k < m.warnings.size(); ++k)
        m.warnings[k] = r.string({nullptr, "warnings", static_cast<long long>(k)});
    r.brep(m);
    r.assembly(m.assembly);
    r.end();
    if (!m.assembly.empty()) validate_assembly(m, file);
    return m;
}

} // namespace seamless
