// SPDX-License-Identifier: MIT
// The assembly in the model exchange form (model_exchange.h): parts, nodes,
// colours, the solids' and faces' colours, and the layers.
#include <seamless/model/model_exchange_codec.h>

namespace seamless::exchange {

void ExchangeWriter::assembly(const Assembly& a) {
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

// The tree's indices and numbers are checked by validate_assembly after the
// whole model is read; here only what reading needs: counts within the bytes
// left, finite numbers.
void ExchangeReader::assembly(Assembly& a) {
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
    a.solid_colours = ints({nullptr, "assembly.solid_colours"});
    a.face_colours = ints({nullptr, "assembly.face_colours"});
    // A layer takes at least its name's length, its flag and 3 counts: 33 bytes.
    a.layers.resize(items({nullptr, "assembly.layers"}, 33));
    for (std::size_t k = 0; k < a.layers.size(); ++k) {
        const Path f{nullptr, "assembly.layers", static_cast<long long>(k)};
        AssemblyLayer& l = a.layers[k];
        l.name = string({&f, "name"});
        l.visible = flag({&f, "visible"});
        l.parts = ints({&f, "parts"});
        l.solids = ints({&f, "solids"});
        l.faces = ints({&f, "faces"});
    }
}

} // namespace seamless::exchange
