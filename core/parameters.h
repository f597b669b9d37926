// eulermap::Parameters — every parameter a host can set, in one table: its name, kind,
// default, limits and help text. The table drives the MeshLab filter's declarations (the
// adapter maps each entry onto a RichParameter), Options::Validate (the only place limits
// are checked), the .mlx scripts of the samples and tests (MlxFilter) and the README's list
// (eulermap_bench parameters; the build rewrites the README's list and samples/*.mlx from it:
// tests/bench/generated.py). Adding a parameter is one entry here plus its use in the core.
#pragma once

#include "options.h"

#include <map>
#include <string>
#include <vector>

namespace eulermap {

enum class ParameterKind { Mesh, Int, Float, Enum, Bool, OpenFile, String };

struct Parameter {
  const char *name;   // snake_case: pymeshlab's keyword, the .mlx name, the one in messages
  ParameterKind kind;
  const char *label;  // the dialog's
  const char *help;   // the dialog's tooltip, pymeshlab's docstring
  std::vector<std::string> choices = {};  // Enum: its values (the value is an index); OpenFile: file filters
  // The Options member it sets, as a number (Bool: 0 or 1, Enum: the choice's index); null
  // for what the host resolves itself (layers, anchor files and pairs).
  double (*get)(const Options &) = nullptr;
  void (*set)(Options &, double) = nullptr;
  // Int and Float: the range, low < value <= high (low itself allowed when lowIncluded),
  // finite; and what the number is, for the message of a value outside.
  double low = 0, high = 0;
  bool lowIncluded = true;
  const char *meaning = "";
  bool inFilter = true;  // false: set by the core's callers only (tests, benchmark)

  double Default() const { return get ? get(Options()) : 0; }
  bool InRange(double value) const;
  // Throws Error "NAME VALUE is out of range: give a number from LOW to HIGH (MEANING; D is the default)".
  void Check(const Options &options) const;
};

// Every parameter; those inFilter in dialog (and .mlx) order, first.
const std::vector<Parameter> &Parameters();
const Parameter &FindParameter(const std::string &name);  // throws Error for an unknown name

// Names the hosts resolve themselves.
namespace parameter {
inline constexpr const char *kSourceMesh = "source_mesh";
inline constexpr const char *kTargetMesh = "target_mesh";
inline constexpr const char *kSourceAnchors = "source_anchors";
inline constexpr const char *kTargetAnchors = "target_anchors";
inline constexpr const char *kAnchorPairs = "anchor_pairs";
}  // namespace parameter

// The value as the .mlx and the README write it: 64, 2, true, centre-and-scale's index.
std::string ValueText(const Parameter &p, double value);

// The filter's name in menus and scripts.
inline constexpr const char *kFilterName = "Eulerian Surface Map";

// A complete meshlabserver <filter> element: every parameter of the filter in order
// (meshlabserver 2020.09 asserts otherwise), defaults unless `values` (name -> text) gives one.
std::string MlxFilter(const std::map<std::string, std::string> &values);

// The README's parameter list: "- `name` (limits, default): the help's first sentence" per
// parameter of the filter.
std::string ParametersMarkdown();

} // namespace eulermap
