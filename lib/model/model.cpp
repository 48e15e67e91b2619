// SPDX-License-Identifier: MIT
#include <seamless/model/model.h>

#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>
#include <seamless/model/step_iges.h>
#include <seamless/spline/knot_insertion.h>

#include <charconv>
#include <cmath>

namespace seamless {

namespace {
// The shortest text that reads back to x (std::to_chars): "0.2", "1.7e+308".
std::string fmt(double x) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

void validate_knots(int degree, int n, const std::vector<double>& U, const std::string& file,
                    const std::string& field) {
    const size_t expected = static_cast<size_t>(n) + degree + 1;
    if (U.size() != expected)
        throw InputError(file, field,
                         "expected " + std::to_string(expected) + " numbers, got " +
                             std::to_string(U.size()));
    for (size_t k = 0; k < U.size(); ++k) {
        if (!std::isfinite(U[k]))
            throw InputError(file, field + "[" + std::to_string(k) + "]", "not a finite number");
        if (std::abs(U[k]) > kMaxCoordinate)
            throw InputError(file, field + "[" + std::to_string(k) + "]",
                             "knot " + fmt(U[k]) + " beyond the limit of " + fmt(kMaxCoordinate) +
                                 " (docs/formats.md, Limits)");
        if (k > 0 && U[k] < U[k - 1])
            throw InputError(file, field + "[" + std::to_string(k) + "]",
                             "knots decrease (" + fmt(U[k]) + " after " + fmt(U[k - 1]) + ")");
    }
    for (size_t k = 0; k < U.size();) {
        size_t e = k;
        while (e < U.size() && U[e] == U[k]) ++e;
        if (static_cast<int>(e - k) > degree + 1)
            throw InputError(file, field,
                             "knot " + fmt(U[k]) + " has multiplicity " + std::to_string(e - k) +
                                 ", above degree+1 = " + std::to_string(degree + 1));
        k = e;
    }
    if (!(U[degree] < U[n]))
        throw InputError(file, field,
                         "empty domain [" + fmt(U[degree]) + ", " + fmt(U[n]) + "] (knots[" +
                             std::to_string(degree) + "] must be below knots[" + std::to_string(n) +
                             "])");
}
// Finite control points within kMaxCoordinate; `field` names the array.
void validate_points(const std::vector<Vec3>& points, const std::string& file,
                     const std::string& field) {
    for (size_t k = 0; k < points.size(); ++k) {
        const Vec3 p = points[k];
        // The field's name only on failure: a model has up to millions of points.
        const auto fk = [&] { return field + "[" + std::to_string(k) + "]"; };
        if (!is_finite(p)) throw InputError(file, fk(), "not a finite point");
        for (int i = 0; i < 3; ++i)
            if (std::abs(p[i]) > kMaxCoordinate)
                throw InputError(file, fk() + "[" + std::to_string(i) + "]",
                                 "coordinate " + fmt(p[i]) + " beyond the limit of " +
                                     fmt(kMaxCoordinate) + " (docs/formats.md, Limits)");
    }
}

// No weights, or n of them in [1/kMaxWeight, kMaxWeight].
void validate_weights(const std::vector<double>& w, size_t n, const std::string& file,
                      const std::string& field) {
    if (w.empty()) return;
    if (w.size() != n)
        throw InputError(file, field,
                         "expected " + std::to_string(n) + " numbers, got " +
                             std::to_string(w.size()));
    for (size_t k = 0; k < n; ++k)
        if (!std::isfinite(w[k]) || !(w[k] > 0))
            throw InputError(file, field + "[" + std::to_string(k) + "]",
                             "weight " + fmt(w[k]) + " is not a positive finite number");
        else if (w[k] > kMaxWeight || w[k] < 1 / kMaxWeight)
            throw InputError(file, field + "[" + std::to_string(k) + "]",
                             "weight " + fmt(w[k]) + " outside " + fmt(1 / kMaxWeight) + ".." +
                                 fmt(kMaxWeight) + " (docs/formats.md, Limits)");
}
} // namespace

void validate_surface(const BSplineSurface& s, const std::string& file, const std::string& f) {
    const std::string pre = f.empty() ? "" : f + ".";
    if (s.degree_u < 1 || s.degree_u > kMaxDegree || s.degree_v < 1 || s.degree_v > kMaxDegree)
        throw InputError(file, pre + "degree",
                         "degrees must be integers in 1.." + std::to_string(kMaxDegree));
    if (s.size_u < s.degree_u + 1 || s.size_v < s.degree_v + 1)
        throw InputError(file, pre + "size",
                         "control net " + std::to_string(s.size_u) + " x " +
                             std::to_string(s.size_v) + " too small for degree [" +
                             std::to_string(s.degree_u) + ", " + std::to_string(s.degree_v) +
                             "] (need at least degree+1 points per direction)");
    validate_knots(s.degree_u, s.size_u, s.knots_u, file, pre + "knots_u");
    validate_knots(s.degree_v, s.size_v, s.knots_v, file, pre + "knots_v");
    const size_t n = static_cast<size_t>(s.size_u) * s.size_v;
    if (s.points.size() != n)
        throw InputError(file, pre + "control_points",
                         "expected " + std::to_string(n) + " points, got " +
                             std::to_string(s.points.size()));
    validate_points(s.points, file, pre + "control_points");
    validate_weights(s.weights, n, file, pre + "weights");
}

void validate_curve(const BSplineCurve& c, const std::string& file, const std::string& f,
                    long long max_points) {
    const std::string pre = f.empty() ? "" : f + ".";
    if (c.degree < 1 || c.degree > kMaxDegree)
        throw InputError(file, pre + "degree",
                         "degree " + std::to_string(c.degree) + " outside 1.." +
                             std::to_string(kMaxDegree));
    if (c.size() > max_points)
        throw InputError(file, pre + "points",
                         std::to_string(c.size()) + " control points exceed the limit of " +
                             std::to_string(max_points));
    if (c.size() < c.degree + 1)
        throw InputError(file, pre + "points",
                         std::to_string(c.size()) + " control points too few for degree " +
                             std::to_string(c.degree) + " (need at least degree+1)");
    validate_knots(c.degree, c.size(), c.knots, file, pre + "knots");
    validate_points(c.points, file, pre + "points");
    validate_weights(c.weights, c.points.size(), file, pre + "weights");
}

Model load_model(const std::filesystem::path& path, const ModelLimits& limits) {
    ModelLoadOptions options;
    options.limits = limits;
    return load_model(path, options);
}

Model load_model(const std::filesystem::path& path, const ModelLoadOptions& options) {
    const ModelLimits& limits = options.limits;
    const std::string file = path.string();
    const std::string text = read_input_file(path, limits.max_file_bytes, "model");
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    Model m = naming_file_on_oom(file, [&] {
        return is_step_iges_extension(ext) ? read_step_iges(path, options)
               : ext == ".bpt"             ? parse_bpt(text, file, limits)
                                           : parse_model_json(text, file, limits);
    });
    m.source = file;
    if (options.keep_assembly || !m.assembly.has_tree()) return m;
    Model flat = naming_file_on_oom(file, [&] { return flatten_assembly(m); });
    // Placements can carry coordinates beyond the limit.
    for (size_t k = 0; k < flat.surfaces.size(); ++k)
        validate_surface(flat.surfaces[k], file, "surfaces[" + std::to_string(k) + "]");
    return flat;
}

Box3 control_box(const Model& m) {
    Box3 b;
    for (const BSplineSurface& s : m.surfaces) b.extend(control_box(s));
    return b;
}

double d_max(const Model& m) {
    return control_box(m).max_extent();
}

std::vector<BezierPatch> bezier_patches(const Model& m) {
    std::vector<BezierPatch> out;
    for (size_t k = 0; k < m.surfaces.size(); ++k) {
        auto ps = bezier_patches(m.surfaces[k], static_cast<int>(k));
        out.insert(out.end(), ps.begin(), ps.end());
    }
    return out;
}

} // namespace seamless
