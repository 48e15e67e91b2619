// SPDX-License-Identifier: MIT
// STEP (ISO 10303-21) and IGES (global section) length units, read as text:
// no OpenCASCADE here, so no reader process is needed for a unit.
#include <seamless/base/files/input_file.h>
#include <seamless/model/length_unit.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace seamless {
namespace {

// The instances of a STEP file ("#12=...;"), whitespace and comments
// outside strings removed, in the file's order.
class StepInstances {
  public:
    explicit StepInstances(const std::string& text) {
        std::string current;
        long id = -1;
        for (size_t i = 0; i < text.size(); ++i) {
            const char c = text[i];
            if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
                const size_t end = text.find("*/", i + 2);
                i = end == std::string::npos ? text.size() : end + 1;
            } else if (c == '\'') { // a string; '' is a quote inside it
                size_t end = i + 1;
                while (end < text.size() &&
                       !(text[end] == '\'' && (end + 1 >= text.size() || text[end + 1] != '\'')))
                    end += text[end] == '\'' ? 2 : 1;
                if (id >= 0) current.append(text, i, end + 1 - i);
                i = end;
            } else if (id < 0 && c == '#') {
                id = start(text, i, current);
            } else if (id >= 0 && c == ';') {
                index_[id] = items_.size();
                items_.push_back(std::move(current));
                current.clear();
                id = -1;
            } else if (id >= 0 && !std::isspace(static_cast<unsigned char>(c))) {
                current += c;
            }
        }
    }
    const std::vector<std::string>& items() const { return items_; }
    const std::string* find(long id) const {
        auto it = index_.find(id);
        return it == index_.end() ? nullptr : &items_[it->second];
    }

  private:
    // At "#<digits>=": its id, `i` moved to the '='; else -1.
    static long start(const std::string& text, size_t& i, std::string& current) {
        size_t k = i + 1;
        long id = 0;
        auto r = std::from_chars(text.data() + k, text.data() + text.size(), id);
        if (r.ec != std::errc()) return -1;
        k = static_cast<size_t>(r.ptr - text.data());
        while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
        if (k >= text.size() || text[k] != '=') return -1;
        i = k;
        current.clear();
        return id;
    }

    std::vector<std::string> items_;
    std::unordered_map<long, size_t> index_;
};

// The reference "#<digits>" at or after `from` in `s`, -1 for none.
long reference_after(const std::string& s, size_t from) {
    const size_t h = s.find('#', from);
    long id = -1;
    if (h != std::string::npos) std::from_chars(s.data() + h + 1, s.data() + s.size(), id);
    return id;
}

// SI prefixes (ISO 10303-41 si_prefix) in metres per unit of a prefixed metre.
double si_prefix(const std::string& p) {
    static const std::pair<const char*, double> table[] = {
        {"$", 1},          {".EXA.", 1e18},  {".PETA.", 1e15},  {".TERA.", 1e12},
        {".GIGA.", 1e9},   {".MEGA.", 1e6},  {".KILO.", 1e3},   {".HECTO.", 1e2},
        {".DECA.", 1e1},   {".DECI.", 1e-1}, {".CENTI.", 1e-2}, {".MILLI.", 1e-3},
        {".MICRO.", 1e-6}, {".NANO.", 1e-9}, {".PICO.", 1e-12}, {".FEMTO.", 1e-15},
        {".ATTO.", 1e-18}};
    for (const auto& [name, f] : table)
        if (p == name) return f;
    return 0;
}

// Metres per the length unit instance `id`: an SI unit, or a conversion-based
// unit through its measure (LENGTH_MEASURE(25.4) of a millimetre); 0 unknown.
double step_unit(const StepInstances& file, long id, int depth) {
    const std::string* s = file.find(id);
    if (!s || depth > 8) return 0;
    if (const size_t si = s->find("SI_UNIT("); si != std::string::npos) {
        const size_t comma = s->find(',', si), close = s->find(')', si);
        if (comma == std::string::npos || close == std::string::npos || close < comma) return 0;
        if (s->substr(comma + 1, close - comma - 1) != ".METRE.") return 0;
        return si_prefix(s->substr(si + 8, comma - si - 8));
    }
    const size_t conversion = s->find("CONVERSION_BASED_UNIT(");
    if (conversion == std::string::npos) return 0;
    const std::string* measure = file.find(reference_after(*s, conversion));
    if (!measure) return 0;
    const size_t m = measure->find("LENGTH_MEASURE(");
    if (m == std::string::npos) return 0;
    const size_t v = m + 15;
    double value = 0;
    auto r = std::from_chars(measure->data() + v, measure->data() + measure->size(), value);
    if (r.ec != std::errc() || !(value > 0)) return 0;
    return value * step_unit(file, reference_after(*measure, v), depth + 1);
}

// The fields of IGES's global section (1-based: field(14) is the unit flag);
// Hollerith strings ("2HMM") become their text.
std::vector<std::string> iges_global_fields(const std::string& g) {
    char pd = ',', rd = ';';
    size_t i = 0;
    // Parameters 1 and 2 name the delimiters ("1H,"), or are empty (',' and ';').
    for (char* d : {&pd, &rd}) {
        if (g.compare(i, 2, "1H") == 0 && i + 2 < g.size()) *d = g[i + 2], i += 3;
        if (i < g.size() && (g[i] == pd || g[i] == rd)) ++i;
    }
    std::vector<std::string> fields{std::string(1, pd), std::string(1, rd)};
    while (i < g.size() && fields.size() < 40) {
        while (i < g.size() && g[i] == ' ') ++i;
        size_t n = 0, k = i;
        while (k < g.size() && std::isdigit(static_cast<unsigned char>(g[k]))) ++k;
        std::string field;
        if (k > i && k < g.size() && g[k] == 'H') {
            std::from_chars(g.data() + i, g.data() + k, n);
            field = g.substr(k + 1, n);
            i = std::min(g.size(), k + 1 + n);
        }
        while (i < g.size() && g[i] != pd && g[i] != rd) field += g[i++];
        while (!field.empty() && field.back() == ' ') field.pop_back();
        fields.push_back(field);
        if (i >= g.size() || g[i] == rd) break;
        ++i;
    }
    return fields;
}

// IGES unit names (parameter 15) in metres.
double iges_unit_name(std::string name) {
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    static const std::pair<const char*, double> table[] = {
        {"IN", 0.0254}, {"INCH", 0.0254}, {"MM", 1e-3}, {"FT", 0.3048}, {"MI", 1609.344}, {"M", 1},
        {"KM", 1e3},    {"MIL", 2.54e-5}, {"UM", 1e-6}, {"CM", 1e-2},   {"UIN", 2.54e-8}};
    for (const auto& [n, f] : table)
        if (name == n) return f;
    return 0;
}

} // namespace

double step_length_unit(const std::string& text) {
    const StepInstances file(text);
    const std::string key = "GLOBAL_UNIT_ASSIGNED_CONTEXT((";
    for (const std::string& s : file.items()) {
        const size_t at = s.find(key);
        if (at == std::string::npos) continue;
        const size_t end = s.find(')', at + key.size());
        for (size_t k = at + key.size(); k < end && k < s.size(); k = s.find(',', k) + 1) {
            const long id = reference_after(s, k);
            const std::string* unit = file.find(id);
            if (unit && unit->find("LENGTH_UNIT(") != std::string::npos)
                if (const double f = step_unit(file, id, 0); f > 0) return f;
            if (s.find(',', k) == std::string::npos) break;
        }
    }
    return 0;
}

double iges_length_unit(const std::string& text) {
    std::string global;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end - start >= 73 && text[start + 72] == 'G') global.append(text, start, 72);
        start = end + 1;
    }
    const std::vector<std::string> f = iges_global_fields(global);
    if (f.size() < 15) return 0;
    static const double flags[] = {0, 0.0254, 1e-3,    0,    0.3048, 1609.344,
                                   1, 1e3,    2.54e-5, 1e-6, 1e-2,   2.54e-8};
    int flag = 0;
    std::from_chars(f[13].data(), f[13].data() + f[13].size(), flag);
    if (flag == 3 || flag < 1 || flag > 11) return iges_unit_name(f[14]);
    return flags[flag];
}

double file_length_unit(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool step = ext == ".step" || ext == ".stp", iges = ext == ".iges" || ext == ".igs";
    if (!step && !iges) return 0;
    const std::string text = read_input_file(path, std::uintmax_t(1) << 31, "model");
    return step ? step_length_unit(text) : iges_length_unit(text);
}

} // namespace seamless
