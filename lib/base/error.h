// SPDX-License-Identifier: MIT
// Bad input is reported as an InputError naming the file and the field, e.g.
//   model.json: surfaces[2].knots_u: expected 11 numbers, got 10
// Internal invariants are SEAMLESS_CHECKs (check.h); InputError is only for what a
// user handed us.
// what() is one printable line: control characters and invalid UTF-8 that a
// hostile file put in a name or token are escaped (printable.h).
#pragma once

#include <seamless/base/printable.h>

#include <stdexcept>
#include <string>

namespace seamless {

class InputError : public std::runtime_error {
  public:
    InputError(std::string file, std::string field, std::string message)
        : std::runtime_error(compose(file, field, message)), file_(std::move(file)),
          field_(std::move(field)), message_(std::move(message)) {}

    const std::string& file() const { return file_; }
    const std::string& field() const { return field_; }
    const std::string& message() const { return message_; }

  private:
    static std::string compose(const std::string& file, const std::string& field,
                               const std::string& message) {
        std::string s = file;
        if (!field.empty()) s += (s.empty() ? "" : ": ") + field;
        return printable(s + (s.empty() ? "" : ": ") + message);
    }
    std::string file_, field_, message_;
};

} // namespace seamless
