// The filter's parameters, declared once for every MeshLab flavour (DESIGN.md: adapter).
//
// Parameters() lists them in dialog (and .mlx) order with their snake_case names,
// defaults, labels and help texts; a flavour's shim turns each ParameterSpec into its own
// RichParameter kind and reads the values back through ReadRequest(). Nothing here knows
// MeshLab's plugin interface; only Qt and the core's Options.
#pragma once

#include "core/pipeline.h"

#include <QString>
#include <QStringList>
#include <QVariant>

#include <functional>
#include <vector>

namespace eulermap::plugin {

// Internal names; pymeshlab derives its keyword arguments from these.
namespace param {
inline const char *const kSourceMesh = "source_mesh";
inline const char *const kTargetMesh = "target_mesh";
inline const char *const kGridResolution = "grid_resolution";
inline const char *const kSteps = "steps";
inline const char *const kAlpha = "alpha";
inline const char *const kHoleRadius = "hole_radius";
inline const char *const kAlign = "align";
inline const char *const kSourceAnchors = "source_anchors";
inline const char *const kTargetAnchors = "target_anchors";
inline const char *const kAnchorPairs = "anchor_pairs";
inline const char *const kFillHoles = "fill_holes";
inline const char *const kTransferTexture = "transfer_texture";
inline const char *const kTransferColorQuality = "transfer_color_quality";
}  // namespace param

enum class ParameterKind { Mesh, Int, Float, Enum, Bool, OpenFile, String };

struct ParameterSpec {
  QString name;
  ParameterKind kind;
  QVariant defaultValue;  // Int: int, Float: double, Enum: index, Bool: bool, files/strings:
                          // QString; Mesh: unused (the shim picks the layer)
  QString label;          // shown in the dialog
  QString help;           // tooltip / pymeshlab docstring
  QStringList choices;    // Enum: the values; OpenFile: the file-dialog filters
};

// In dialog order. Mesh parameters come first: source (default: the current layer) and
// target (default: the first other layer).
const std::vector<ParameterSpec> &Parameters();

// Menu name, one-line description, long HTML description citing the paper.
QString FilterName();       // "Eulerian Surface Map"
QString FilterDescription();

// What the user asked for, independent of the MeshLab flavour.
struct Request {
  int sourceLayer = -1;  // the layer's number as the flavour names layers (2020.09: its
                         // position in the document, 2025.07: its id); -1: none
  int targetLayer = -1;
  Options options;
  QString sourceAnchors;  // .pp file; empty: the .pp beside the source's file, if any
  QString targetAnchors;
  QString anchorPairs;    // "12:305, 40:77"; the other way to give anchors
  bool transferColorQuality = false;  // the target's vertex colour and quality onto the cut,
                                      // those the target has (MapLayers sets the Options)
};

// Reads every parameter through `value` (called once per ParameterSpec; Mesh parameters
// must come back as the layer's number, as in Request, -1 when none) into a Request.
Request ReadRequest(const std::function<QVariant(const ParameterSpec &)> &value);

}  // namespace eulermap::plugin
