// SPDX-License-Identifier: MIT
// The "assembly" object of the version-2 JSON model format (docs/formats.md,
// "Assembly, names and colours"): read before validate_assembly checks it
// against the B-rep, written only for a model that has one.
#include <seamless/model/brep_json.h>

#include <algorithm>
#include <climits>

namespace seamless {
namespace {

// An index in -1..limit-1 or null (-1): what a part's colour, a node's parent
// and part are; validate_assembly checks them against their lists.
int optional_index(const JsonFields& r, const Json& obj, const std::string& parent, const char* key,
                   long long limit) {
    const Json* j = JsonFields::find(obj, key);
    if (!j || j->is_null()) return -1;
    const long long last = std::min<long long>(limit, INT_MAX) - 1;
    return static_cast<int>(r.integer(*j, member_field(parent, key), -1, last));
}

const Json& list_or_empty(const JsonFields& r, const Json& obj, const std::string& parent,
                          const char* key, long long limit) {
    static const Json empty = Json::array();
    const Json* j = JsonFields::find(obj, key);
    if (!j) return empty;
    const std::string f = member_field(parent, key);
    r.array(*j, f);
    if (static_cast<long long>(j->size()) > limit)
        r.fail(f,
               std::to_string(j->size()) + " items exceed the limit of " + std::to_string(limit));
    return *j;
}

AssemblyPart read_part(const JsonFields& r, const Json& js, const std::string& f, long long n) {
    r.object(js, f);
    AssemblyPart p;
    p.name = r.string(r.member(js, "name", f + ".name"), f + ".name");
    const auto count = [&](const char* key) {
        return static_cast<int>(r.integer_or(js, f, key, 0, 0, std::min<long long>(n, INT_MAX)));
    };
    p.face_count = count("faces");
    p.shell_count = count("shells");
    p.solid_count = count("solids");
    p.colour = optional_index(r, js, f, "colour", n);
    return p;
}

AssemblyNode read_node(const JsonFields& r, const Json& js, const std::string& f, long long n) {
    r.object(js, f);
    AssemblyNode node;
    node.name = r.string(r.member(js, "name", f + ".name"), f + ".name");
    node.parent = optional_index(r, js, f, "parent", n);
    node.part = optional_index(r, js, f, "part", n);
    if (const Json* pl = JsonFields::find(js, "placement")) {
        const std::string fp = f + ".placement";
        r.array(*pl, fp);
        if (pl->size() != 12)
            r.fail(fp, "expected 12 numbers (3 rows of 4), got " + std::to_string(pl->size()));
        const std::vector<double> m = r.numbers(*pl, fp);
        std::copy(m.begin(), m.end(), node.placement.m);
    }
    return node;
}

Rgba read_colour(const JsonFields& r, const Json& js, const std::string& f) {
    r.array(js, f);
    if (js.size() != 4)
        r.fail(f, "expected [r, g, b, a], got " + std::to_string(js.size()) + " numbers");
    const auto c = [&](size_t k) { return r.number(js[k], element_field(f, k), 0, 1); };
    return {c(0), c(1), c(2), c(3)};
}

// A list of indices in lo..n-1 (colour indices: -1 for none), absent: empty;
// validate_assembly checks them against their lists.
std::vector<int> read_indices(const JsonFields& r, const Json& obj, const std::string& parent,
                              const char* key, long long n, int lo) {
    const std::string f = member_field(parent, key);
    const Json& j = list_or_empty(r, obj, parent, key, n);
    std::vector<int> out;
    out.reserve(j.size());
    for (size_t k = 0; k < j.size(); ++k)
        out.push_back(static_cast<int>(
            r.integer(j[k], element_field(f, k), lo, std::min<long long>(n, INT_MAX) - 1)));
    return out;
}

AssemblyLayer read_layer(const JsonFields& r, const Json& js, const std::string& f, long long n) {
    r.object(js, f);
    AssemblyLayer layer;
    layer.name = r.string(r.member(js, "name", f + ".name"), f + ".name");
    if (const Json* v = JsonFields::find(js, "visible")) {
        if (!v->is_boolean())
            r.fail(f + ".visible", "expected true or false, got " + JsonFields::type_name(*v));
        layer.visible = v->get<bool>();
    }
    layer.parts = read_indices(r, js, f, "parts", n, 0);
    layer.solids = read_indices(r, js, f, "solids", n, 0);
    layer.faces = read_indices(r, js, f, "faces", n, 0);
    return layer;
}

void write_name(std::ostream& os, const std::string& name) {
    os << "{\"name\": ";
    write_json_string(os, name);
}

void write_index(std::ostream& os, const char* key, int k) {
    os << ", \"" << key << "\": ";
    if (k < 0)
        os << "null";
    else
        os << k;
}

void write_indices(std::ostream& os, const char* key, const std::vector<int>& v) {
    os << ",\n   \"" << key << "\": ";
    write_json_ints(os, v);
}

void write_layers(std::ostream& os, const std::vector<AssemblyLayer>& layers) {
    os << ",\n  \"layers\": [";
    for (size_t k = 0; k < layers.size(); ++k) {
        const AssemblyLayer& l = layers[k];
        os << (k ? ",\n   " : "\n   ");
        write_name(os, l.name);
        os << ", \"visible\": " << (l.visible ? "true" : "false");
        for (const auto& [key, list] :
             {std::pair{"parts", &l.parts}, std::pair{"solids", &l.solids},
              std::pair{"faces", &l.faces}}) {
            os << ", \"" << key << "\": ";
            write_json_ints(os, *list);
        }
        os << '}';
    }
    os << ']';
}

} // namespace

void read_assembly_json(const JsonFields& r, const Json& j, const ModelLimits& limits,
                        Assembly& a) {
    const std::string f = "assembly";
    r.object(j, f);
    const long long n = limits.max_brep_items;
    const Json& parts = list_or_empty(r, j, f, "parts", n);
    for (size_t k = 0; k < parts.size(); ++k)
        a.parts.push_back(read_part(r, parts[k], element_field(f + ".parts", k), n));
    const Json& nodes = list_or_empty(r, j, f, "nodes", n);
    for (size_t k = 0; k < nodes.size(); ++k)
        a.nodes.push_back(read_node(r, nodes[k], element_field(f + ".nodes", k), n));
    const Json& colours = list_or_empty(r, j, f, "colours", n);
    for (size_t k = 0; k < colours.size(); ++k)
        a.colours.push_back(read_colour(r, colours[k], element_field(f + ".colours", k)));
    a.solid_colours = read_indices(r, j, f, "solid_colours", n, -1);
    a.face_colours = read_indices(r, j, f, "face_colours", n, -1);
    const Json& layers = list_or_empty(r, j, f, "layers", n);
    for (size_t k = 0; k < layers.size(); ++k)
        a.layers.push_back(read_layer(r, layers[k], element_field(f + ".layers", k), n));
}

void write_assembly_json(std::ostream& os, const Assembly& a) {
    os << "{\"parts\": [";
    for (size_t k = 0; k < a.parts.size(); ++k) {
        const AssemblyPart& p = a.parts[k];
        os << (k ? ",\n   " : "\n   ");
        write_name(os, p.name);
        os << ", \"faces\": " << p.face_count << ", \"shells\": " << p.shell_count
           << ", \"solids\": " << p.solid_count;
        write_index(os, "colour", p.colour);
        os << '}';
    }
    os << "],\n  \"nodes\": [";
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        const AssemblyNode& n = a.nodes[k];
        os << (k ? ",\n   " : "\n   ");
        write_name(os, n.name);
        write_index(os, "parent", n.parent);
        write_index(os, "part", n.part);
        os << ", \"placement\": [";
        for (int i = 0; i < 12; ++i) {
            if (i) os << ", ";
            write_json_number(os, n.placement.m[i]);
        }
        os << "]}";
    }
    os << "],\n  \"colours\": [";
    for (size_t k = 0; k < a.colours.size(); ++k) {
        const Rgba& c = a.colours[k];
        os << (k ? ", " : "") << '[';
        write_json_number(os, c.r);
        os << ", ";
        write_json_number(os, c.g);
        os << ", ";
        write_json_number(os, c.b);
        os << ", ";
        write_json_number(os, c.a);
        os << ']';
    }
    os << ']';
    if (!a.solid_colours.empty()) write_indices(os, "solid_colours", a.solid_colours);
    if (!a.face_colours.empty()) write_indices(os, "face_colours", a.face_colours);
    if (!a.layers.empty()) write_layers(os, a.layers);
    os << '}';
}

} // namespace seamless
