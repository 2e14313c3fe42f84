#pragma once
// One entry of a stage's parameter table: the pipeline key (snake_case; the command-line
// option is the same with dashes), its unit as users write it, its default, the values
// it accepts and its help text. It is bound to one field of the stage's settings struct:
// `assign` parses, checks and stores a value given as text, `value` reads the field back.
// The default is the field's value when the entry was made, i.e. the settings struct's
// default member initialiser: one set of defaults for the library, the CLI and the docs.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/core/NumberRange.h"

namespace vesica {

// NOLINTNEXTLINE(bugprone-exception-escape): the check counts nlohmann::json's noexcept move
struct Parameter {
  enum class Kind {
    Number,   // finite real within `range`
    Integer,  // whole number within `range`
    Flag,     // present or not (`--fluid`; `fluid: true` in a pipeline file)
    Choice,   // one of `choices`
    Text,     // free form described by `syntax` ("x,y,z or auto"), checked by `assign`
    Input,    // a named input file (`--measured F`), given under a stage's `inputs:`
  };

  std::string name;  // pipeline key: "edge_mm"
  Kind kind = Kind::Number;
  std::string unit;  // "mm", "kPa", "ml", "cmH2O", "ml/min", "s", "-"; empty for text
  std::string help;
  NumberRange range;                 // Number, Integer
  std::vector<std::string> choices;  // Choice
  std::string syntax;                // Text: the accepted form
  // Text: the value names a file the stage writes (`export_feb`): the runner keeps it
  // inside the workdir and backs up what is there, as for the stage's output.
  bool names_output = false;
  nlohmann::json default_value;

  // Parses, checks and stores `text`; throws ParameterValueError saying what is wrong.
  std::function<void(const std::string& text)> assign;
  // The bound field's current value.
  std::function<nlohmann::json()> value;

  // "--edge-mm"
  std::string option() const;
  // What is accepted, for help and errors: "[0.5, 50] mm", "one of sphere, pouch".
  std::string accepted() const;
  // "4 mm", "auto", "off": the default as a user reads it (a special number bare: "0").
  std::string default_text() const;
  // Everything above as JSON (for `--parameters-json`, the runner and the docs).
  nlohmann::json describe() const;
};

const char* kind_name(Parameter::Kind kind);

}  // namespace vesica
