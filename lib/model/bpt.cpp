// SPDX-License-Identifier: MIT
// Reader of the Newell Bezier patch format (.bpt): the patch count, then per
// patch a line "p q" (degrees) and (p+1)*(q+1) lines "x y z", row by row; point
// k = (q+1)*r + c is control point (i, j) = (r, c). The teaset uses "3 3".
#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <charconv>
#include <cmath>

namespace seamless {
namespace {

struct Token {
    std::string_view text;
    int line;
};

std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> out;
    int line = 1;
    size_t k = 0;
    while (k < text.size()) {
        char c = text[k];
        if (c == '\n') {
            ++line, ++k;
        } else if (c == '#') { // comment to end of line, as some copies carry
            while (k < text.size() && text[k] != '\n') ++k;
        } else if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
            ++k;
        } else {
            size_t e = k;
            while (e < text.size() && !std::isspace(static_cast<unsigned char>(text[e])) &&
                   text[e] != ',' && text[e] != '#')
                ++e;
            out.push_back({std::string_view(text).substr(k, e - k), line});
            k = e;
        }
    }
    return out;
}

} // namespace

Model parse_bpt(const std::string& text, const std::string& file, const ModelLimits& limits) {
    const std::vector<Token> tok = tokenize(text);
    size_t at = 0;
    auto where = [&](size_t k) {
        return "line " +
               std::to_string(k < tok.size() ? tok[k].line : (tok.empty() ? 1 : tok.back().line));
    };
    auto number = [&](const std::string& what) {
        if (at >= tok.size())
            throw InputError(file, where(at), "unexpected end of file, expected " + what);
        std::string s(tok[at].text);
        char* end = nullptr;
        double x = std::strtod(s.c_str(), &end);
        if (end != s.c_str() + s.size())
            throw InputError(file, where(at), "expected " + what + ", got '" + s + "'");
        if (!std::isfinite(x)) throw InputError(file, where(at), what + " is not a finite number");
        ++at;
        return x;
    };
    auto integer = [&](const std::string& what, long long lo, long long hi) {
        size_t here = at;
        double x = number(what);
        if (x != std::floor(x) || x < static_cast<double>(lo) || x > static_cast<double>(hi))
            throw InputError(file, where(here),
                             what + " must be an integer in " + std::to_string(lo) + ".." +
                                 std::to_string(hi));
        return static_cast<long long>(x);
    };
    if (tok.empty()) throw InputError(file, "line 1", "empty file, expected the patch count");
    const long long count = integer("patch count", 1, limits.max_surfaces);
    // Each patch needs at least 2 + 3*4 numbers (degree 1 x 1): reject a count the
    // file cannot hold before reserving anything for it.
    if (static_cast<unsigned long long>(count) * 14 > tok.size())
        throw InputError(file, "line 1",
                         "patch count " + std::to_string(count) + " exceeds what the file holds (" +
                             std::to_string(tok.size()) + " numbers)");
    Model m;
    m.source = file;
    m.surfaces.reserve(static_cast<size_t>(count));
    for (long long n = 0; n < count; ++n) {
        const std::string f = "patch " + std::to_string(n);
        BSplineSurface s;
        s.name = "patch-" + std::to_string(n);
        s.degree_u = static_cast<int>(integer(f + " degree u", 1, kMaxDegree));
        s.degree_v = static_cast<int>(integer(f + " degree v", 1, kMaxDegree));
        s.size_u = s.degree_u + 1;
        s.size_v = s.degree_v + 1;
        s.knots_u.assign(s.size_u, 0.0);
        s.knots_u.resize(2 * s.size_u, 1.0);
        s.knots_v.assign(s.size_v, 0.0);
        s.knots_v.resize(2 * s.size_v, 1.0);
        for (int k = 0; k < s.size_u * s.size_v; ++k) {
            const std::string fp = f + " point " + std::to_string(k);
            double x = number(fp + " x"), y = number(fp + " y"), z = number(fp + " z");
            s.points.push_back({x, y, z});
        }
        validate_surface(s, file, f);
        m.surfaces.push_back(std::move(s));
    }
    if (at != tok.size())
        throw InputError(file, where(at),
                         "unexpected '" + std::string(tok[at].text) + "' after the last patch");
    return m;
}

} // namespace seamless
