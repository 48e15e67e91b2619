// SPDX-License-Identifier: MIT
// The model exchange form (model_exchange.h): the model itself, its surfaces
// and curves. The layout is model_exchange_codec.h's; the B-rep and the
// assembly are in model_exchange_brep.cpp and model_exchange_assembly.cpp.
#include <seamless/model/model_exchange.h>

#include <seamless/model/model_exchange_codec.h>

namespace seamless {
namespace exchange {

// A member added to one of these types must be written and read in the
// model_exchange files; the sizes (x86-64, libstdc++) stop the build until it is.
static_assert(sizeof(Model) == 416 && sizeof(BRep) == 168 && sizeof(Assembly) == 144 &&
                  sizeof(AssemblyPart) == 48 && sizeof(AssemblyNode) == 144 && sizeof(Rgba) == 32 &&
                  sizeof(AssemblyLayer) == 112 && sizeof(SurfaceOrigin) == 80 &&
                  sizeof(BSplineSurface) == 144 && sizeof(BSplineCurve) == 80 &&
                  sizeof(BRepFace) == 64 && sizeof(BRepEdge) == 40 && sizeof(BRepSolid) == 56 &&
                  sizeof(BRepShell) == 32 && sizeof(BRepCoedge) == 12 && sizeof(BRepVertex) == 32,
              "a member was added to Model or its parts: write and read it in model_exchange*.cpp");

void ExchangeWriter::model(const Model& m) {
    bytes(kTag.data(), kTag.size());
    string(m.source);
    list(m.surfaces, [&](const BSplineSurface& s) { surface(s); });
    list(m.origins, [&](const SurfaceOrigin& o) {
        string(o.entity);
        string(o.kind);
        scalar<std::uint8_t>(o.exact);
        scalar(o.approximation_error);
    });
    list(m.warnings, [&](const std::string& s) { string(s); });
    brep(m.brep);
    assembly(m.assembly);
}

void ExchangeWriter::surface(const BSplineSurface& s) {
    string(s.name);
    for (int i : {s.degree_u, s.degree_v, s.size_u, s.size_v}) scalar<std::int32_t>(i);
    array(s.knots_u);
    array(s.knots_v);
    array(s.points);
    array(s.weights);
}

void ExchangeWriter::curve(const BSplineCurve& c) {
    scalar<std::int32_t>(c.degree);
    array(c.knots);
    array(c.points);
    array(c.weights);
}

std::string ExchangePath::str() const {
    std::string s = parent ? parent->str() : std::string();
    if (*name) {
        if (!s.empty()) s += '.';
        s += name;
    }
    if (index >= 0) {
        s += '[';
        s += std::to_string(index);
        s += ']';
    }
    return s;
}

void ExchangeReader::fail(const Path& field, const std::string& message) const {
    std::string f = "exchange";
    if (const std::string path = field.str(); !path.empty()) f += '.' + path;
    throw InputError(file_, f, message);
}

Model ExchangeReader::model() {
    tag();
    Model m;
    m.source = string({nullptr, "source"});
    // A surface takes at least its name's length, 4 ints and 4 counts: 56 bytes.
    m.surfaces.resize(count({nullptr, "surfaces"}, limits_.max_surfaces, 56));
    for (std::size_t k = 0; k < m.surfaces.size(); ++k)
        m.surfaces[k] = surface({nullptr, "surfaces", static_cast<long long>(k)});
    const std::size_t origins = count({nullptr, "origins"}, limits_.max_surfaces, 25);
    if (origins != 0 && origins != m.surfaces.size())
        fail({nullptr, "origins"}, std::to_string(origins) + " origins for " +
                                       std::to_string(m.surfaces.size()) + " surfaces");
    m.origins.resize(origins);
    for (std::size_t k = 0; k < origins; ++k) {
        const Path f{nullptr, "origins", static_cast<long long>(k)};
        SurfaceOrigin& o = m.origins[k];
        o.entity = string({&f, "entity"});
        o.kind = string({&f, "kind"});
        o.exact = flag({&f, "exact"});
        o.approximation_error = scalar<double>({&f, "approximation_error"});
    }
    m.warnings.resize(count({nullptr, "warnings"}, limits_.max_surfaces, 8));
    for (std::size_t k = 0; k < m.warnings.size(); ++k)
        m.warnings[k] = string({nullptr, "warnings", static_cast<long long>(k)});
    brep(m);
    assembly(m.assembly);
    end();
    if (!m.assembly.empty()) validate_assembly(m, file_);
    return m;
}

BSplineSurface ExchangeReader::surface(const Path& f) {
    BSplineSurface s;
    s.name = string({&f, "name"});
    s.degree_u = integer({&f, "degree"});
    s.degree_v = integer({&f, "degree"});
    s.size_u = integer({&f, "size"});
    s.size_v = integer({&f, "size"});
    const long long n = limits_.max_control_points;
    s.knots_u = array<double>({&f, "knots_u"}, n + kMaxDegree + 1);
    s.knots_v = array<double>({&f, "knots_v"}, n + kMaxDegree + 1);
    s.points = array<Vec3>({&f, "control_points"}, n);
    s.weights = array<double>({&f, "weights"}, n);
    validate_surface(s, file_, "exchange." + f.str());
    return s;
}

BSplineCurve ExchangeReader::curve(const Path& f) {
    BSplineCurve c;
    c.degree = integer({&f, "degree"});
    const long long n = limits_.max_curve_points;
    c.knots = array<double>({&f, "knots"}, n + kMaxDegree + 1);
    c.points = array<Vec3>({&f, "points"}, n);
    c.weights = array<double>({&f, "weights"}, n);
    validate_curve(c, file_, "exchange." + f.str(), n);
    return c;
}

} // namespace exchange

std::string write_model_exchange(const Model& m) {
    exchange::ExchangeWriter w(static_cast<std::size_t>(model_exchange_size(m)));
    w.model(m);
    return std::move(w.out);
}

std::uint64_t model_exchange_size(const Model& m) {
    exchange::ExchangeWriter w;
    w.model(m);
    return w.size();
}

bool write_model_exchange(const Model& m,
                          const std::function<bool(const char*, std::size_t)>& sink) {
    exchange::ExchangeWriter w(sink);
    w.model(m);
    return w.finish();
}

Model read_model_exchange(std::string_view bytes, const std::string& file,
                          const ModelLimits& limits) {
    return exchange::ExchangeReader(bytes, file, limits).model();
}

} // namespace seamless
