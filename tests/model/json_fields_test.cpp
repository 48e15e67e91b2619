// SPDX-License-Identifier: MIT
// JsonFields: the one wording of the JSON readers (models and scenes) for a
// missing field, a wrong type, a number that is not finite or out of range
// and a syntax error, each message naming the file and the field.
#include <seamless/base/error.h>
#include <seamless/model/json_fields.h>

#include <catch2/catch.hpp>

#include <functional>

using namespace seamless;

namespace {

// The message of the InputError f throws ("" if none), checked to name file.json.
std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        CHECK(e.file() == "file.json");
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("field names: members with a dot below their parent, elements in brackets",
          "[model][json]") {
    CHECK(member_field("camera", "eye") == "camera.eye");
    CHECK(member_field("", "levels") == "levels");
    CHECK(element_field("surfaces", 2) == "surfaces[2]");
    CHECK(element_field(member_field("camera", "eye"), 1) == "camera.eye[1]");
}

TEST_CASE("JsonFields: one wording for each defect, naming file and field", "[model][json]") {
    const JsonFields r("file.json");
    const Json doc = r.parse_object(
        R"({"version": 1, "n": 4.0, "x": 2.5, "s": "a", "big": 18446744073709551615,
            "v": [1, 2, 3], "o": {"a": 1}, "l": [1, "two"]})");
    CHECK(error_of([&] { r.check_version(doc); }).empty());
    CHECK(r.integer(doc["n"], "n", 0, 10) == 4);
    CHECK(r.number(doc["x"], "x") == 2.5);
    CHECK(r.string(doc["s"], "s") == "a");
    CHECK(r.vec3(doc["v"], "v").z == 3);
    CHECK(r.number_or(doc, "", "missing", 7, 0, 10) == 7);
    CHECK(r.integer_or(doc["o"], "o", "a", 5, 0, 10) == 1);
    CHECK(JsonFields::find(doc, "missing") == nullptr);

    CHECK(error_of([&] { r.member(doc["o"], "b", "o.b"); }) == "file.json: o.b: missing");
    CHECK(error_of([&] { r.number(doc["s"], "s"); }) ==
          "file.json: s: expected a number, got a string");
    CHECK(error_of([&] { r.integer(doc["x"], "x", 0, 10); }) ==
          "file.json: x: expected an integer");
    CHECK(error_of([&] { r.integer(doc["v"], "v", 0, 10); }) ==
          "file.json: v: expected an integer, got an array");
    CHECK(error_of([&] { r.integer(doc["n"], "n", 5, 10); }) ==
          "file.json: n: value 4.0 out of range 5..10");
    CHECK(error_of([&] { r.integer(doc["big"], "big", 0, 10); }) ==
          "file.json: big: value 18446744073709551615 out of range 0..10");
    CHECK(error_of([&] { r.number_or(doc, "", "x", 0, 0, 1); }) ==
          "file.json: x: value 2.5 out of range 0..1");
    CHECK(error_of([&] { r.array(doc["o"], "o"); }) ==
          "file.json: o: expected an array, got an object");
    CHECK(error_of([&] { r.object(doc["l"], "l"); }) ==
          "file.json: l: expected an object, got an array");
    CHECK(error_of([&] { r.string(doc["n"], "n", "a file name"); }) ==
          "file.json: n: expected a file name, got a number");
    CHECK(error_of([&] { r.numbers(doc["l"], "l"); }) ==
          "file.json: l[1]: expected a number, got a string");
    CHECK(error_of([&] { r.vec3(doc["l"], "l"); }) == "file.json: l: expected [x, y, z]");
}

TEST_CASE("JsonFields::parse_object: syntax errors by line and column, overflow by field",
          "[model][json]") {
    const JsonFields r("file.json");
    CHECK_THAT(error_of([&] { r.parse_object("{\n  \"a\": [1,\n  }"); }),
               Catch::StartsWith("file.json: line 3, column 3: JSON syntax error"));
    CHECK(error_of([&] { r.parse_object(R"({"a": {"b": [0, 1e999]}})"); }) ==
          "file.json: a.b[1]: not a finite number (overflows a double)");
    CHECK(error_of([&] { r.parse_object("[1]"); }) ==
          "file.json: expected a JSON object at the top level");
    CHECK(error_of([&] { r.check_version(r.parse_object(R"({"version": 2})")); }) ==
          "file.json: version: unsupported version 2 (this reader knows 1)");
    CHECK(error_of([&] { r.check_version(r.parse_object("{}")); }) ==
          "file.json: version: missing");
}
