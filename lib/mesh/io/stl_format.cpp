// SPDX-License-Identifier: MIT
// STL: every triangle carries its own three corners, so reading gives 3 vertices
// per triangle (no welding). Binary STL stores float32; we write ASCII STL with
// shortest round-trip doubles, which this reader restores bit-identically (other
// programs usually round them to float).
#include <seamless/mesh/io/mesh_text.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

namespace seamless::mesh_text {

namespace {

// A little-endian float32 of binary STL at `p`.
double load_float32_le(const unsigned char* p) {
    unsigned char b[4];
    for (int i = 0; i < 4; ++i) b[i] = std::endian::native == std::endian::big ? p[3 - i] : p[i];
    float v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
}

// A token for a message: 'facet', or the end of the file.
std::string token_text(std::string_view t) {
    if (t.empty()) return "the end of the file";
    std::string s(1, '\'');
    s.append(t);
    s += '\'';
    return s;
}

} // namespace

TriangleMesh read_stl(const std::string& text, const std::string& file) {
    TriangleMesh mesh;
    bool binary = false;
    if (text.size() >= 84) {
        uint32_t n;
        std::memcpy(&n, text.data() + 80, 4);
        if constexpr (std::endian::native == std::endian::big) n = __builtin_bswap32(n);
        binary = 84 + 50ull * n == text.size();
    }
    if (!binary && text.compare(0, 5, "solid") != 0)
        throw InputError(file, "", "neither ASCII STL ('solid') nor binary STL of consistent size");
    if (binary) {
        uint32_t n;
        std::memcpy(&n, text.data() + 80, 4);
        mesh.positions.reserve(3ull * n);
        for (uint32_t f = 0; f < n; ++f) {
            const auto* rec = reinterpret_cast<const unsigned char*>(text.data()) + 84 + 50ull * f;
            for (int c = 0; c < 3; ++c) {
                Vec3 p;
                for (int k = 0; k < 3; ++k) p[k] = load_float32_le(rec + 12 + 12 * c + 4 * k);
                mesh.positions.push_back(p);
            }
            const int b = static_cast<int>(3 * f);
            mesh.triangles.push_back({b, b + 1, b + 2});
        }
        return mesh;
    }
    // ASCII STL, strictly: one or more "solid [name]" ... "endsolid [name]",
    // each holding facets "facet normal nx ny nz / outer loop / vertex x y z
    // (three times) / endloop / endfacet". Anything else is an error.
    Tokens in(text, file);
    auto expect = [&](std::string_view want) {
        const auto t = in.next();
        if (t != want) in.fail("expected '" + std::string(want) + "', got " + token_text(t));
    };
    for (auto t = in.next(); !t.empty(); t = in.next()) {
        if (t != "solid") in.fail("expected 'solid', got '" + std::string(t) + "'");
        in.next_line(); // the solid's name
        for (;;) {
            const auto k = in.next();
            if (k == "endsolid") {
                in.next_line();
                break;
            }
            if (k != "facet")
                in.fail(k.empty() ? std::string("file ends inside a solid (no 'endsolid')")
                                  : "expected 'facet' or 'endsolid', got '" + std::string(k) + "'");
            expect("normal");
            for (int i = 0; i < 3; ++i) in.number(in.next());
            expect("outer");
            expect("loop");
            for (int c = 0; c < 3; ++c) {
                const auto v = in.next();
                if (v == "endloop") in.fail("facet with " + std::to_string(c) + " vertices");
                if (v != "vertex") in.fail("expected 'vertex', got " + token_text(v));
                Vec3 p;
                p.x = in.number(in.next());
                p.y = in.number(in.next());
                p.z = in.number(in.next());
                mesh.positions.push_back(p);
            }
            const auto e = in.next();
            if (e == "vertex") in.fail("facet with more than 3 vertices");
            if (e != "endloop") in.fail("expected 'endloop', got " + token_text(e));
            expect("endfacet");
            const int b = mesh.vertex_count() - 3;
            mesh.triangles.push_back({b, b + 1, b + 2});
        }
    }
    return mesh;
}

std::string format_stl(const TriangleMesh& mesh) {
    std::string out = "solid seamless\n";
    for (auto& t : mesh.triangles) {
        const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        out += "facet normal ";
        append_point(out, normalize(cross(b - a, c - a)));
        out += "\n outer loop\n";
        for (Vec3 p : {a, b, c}) {
            out += "  vertex ";
            append_point(out, p);
            out += '\n';
        }
        out += " endloop\nendfacet\n";
    }
    out += "endsolid seamless\n";
    return out;
}

} // namespace seamless::mesh_text
