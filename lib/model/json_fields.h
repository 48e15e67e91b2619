// SPDX-License-Identifier: MIT
// The fields of a JSON document read with one wording for every defect, for
// the two JSON readers: models (model_json.cpp) and scenes
// (render/scene/scene.cpp). Each message names the file and the field
// (docs/formats.md, Errors):
//   model.json: line 3, column 7: JSON syntax error while parsing object - ...
//   model.json: surfaces[0].knots_u[3]: not a finite number
//   scene.json: camera.width: value 0 out of range 1..16384
//   scene.json: lights: expected an array, got an object
//   scene.json: camera.eye: missing
// Internal to those readers: it exposes nlohmann::json, which no other header
// of seamless does; the rest of the library sees their plain types.
#pragma once

#include <seamless/base/vec.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace seamless {

using Json = nlohmann::json;

// A member's field name below its parent: ("camera", "eye") -> "camera.eye",
// ("", "levels") -> "levels".
std::string member_field(const std::string& parent, const std::string& key);
// An element's field name: ("surfaces", 2) -> "surfaces[2]".
std::string element_field(const std::string& array, std::size_t k);

// The writers' side (model_json.cpp, brep_json.cpp): x with 17 significant
// digits, which reads back bit-identical (-0 as "-0.0": "-0" reads back +0);
// a string quoted and escaped; a list of indices on one line.
void write_json_number(std::ostream& os, double x);
void write_json_string(std::ostream& os, const std::string& s);
void write_json_ints(std::ostream& os, const std::vector<int>& v);

// Reads the fields of one file's document; every defect throws an InputError
// naming the file and the field.
class JsonFields {
  public:
    explicit JsonFields(std::string file) : file_(std::move(file)) {}
    const std::string& file() const { return file_; }

    [[noreturn]] void fail(const std::string& field, const std::string& message) const;

    // The document, which must be an object. A syntax error is named by line
    // and column, a number that overflows a double by its field.
    Json parse_object(const std::string& text) const;
    // The root's "version": present, an integer in 1..newest; returned.
    int check_version(const Json& root, int newest = 1) const;

    // The member `key` of obj, whose field name is `field`; "missing" if absent.
    const Json& member(const Json& obj, const std::string& key, const std::string& field) const;
    // The member `key` of obj, or nullptr if absent.
    static const Json* find(const Json& obj, const std::string& key);

    // j as an object, an array, a string: "expected WHAT, got a number" otherwise.
    const Json& object(const Json& j, const std::string& field,
                       const std::string& what = "an object") const;
    const Json& array(const Json& j, const std::string& field) const;
    std::string string(const Json& j, const std::string& field,
                       const std::string& what = "a string") const;
    // A finite number; within [lo, hi] for the second.
    double number(const Json& j, const std::string& field) const;
    double number(const Json& j, const std::string& field, double lo, double hi) const;
    // An integer in [lo, hi]; 4.0 counts as 4.
    long long integer(const Json& j, const std::string& field, long long lo, long long hi) const;
    // [x, y, z] of finite numbers.
    Vec3 vec3(const Json& j, const std::string& field) const;
    // [u, v] of finite numbers, as (u, v, 0): a point of a pcurve.
    Vec3 uv(const Json& j, const std::string& field) const;
    // An array of finite numbers.
    std::vector<double> numbers(const Json& j, const std::string& field) const;

    // Optional members of obj (parent: obj's field name): `fallback` when absent.
    double number_or(const Json& obj, const std::string& parent, const std::string& key,
                     double fallback, double lo, double hi) const;
    long long integer_or(const Json& obj, const std::string& parent, const std::string& key,
                         long long fallback, long long lo, long long hi) const;

    // "a string", "an array", ...: what j is, for messages.
    static std::string type_name(const Json& j);

  private:
    std::string file_;
};

} // namespace seamless
