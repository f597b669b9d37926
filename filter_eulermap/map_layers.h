// The filter's work between MeshLab's layers and the core, for every MeshLab flavour:
// checking the request, resolving anchors, running eulermap::ComputeMap with progress,
// turning every failure into a message that says what to change, and the log's lines.
// The flavour's shim only copies layers in and out (mesh_convert.h) and talks to MeshLab.
#pragma once

#include "mesh_convert.h"
#include "parameters.h"

#include <QString>
#include <QStringList>
#include <QVariant>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace eulermap::plugin {

// A layer copied into the core's type.
struct InputLayer {
  QString label;     // the layer's name in MeshLab
  QString fileName;  // the file it was loaded from (empty for layers made by filters)
  LayerComponents has;
  Mesh mesh;
};

// Checks the layer choice before anything is copied: a target given, other than the
// source, both existing. `layers` are the numbers of the document's layers as the flavour
// names them (the request's sourceLayer / targetLayer are such numbers).
bool CheckLayerChoice(const Request &request, const std::vector<int> &layers, QString &error);

// The default target_mesh: the first of `layers` other than `current`; `current` when there
// is none (then CheckLayerChoice says that a target is missing).
int DefaultTargetLayer(int current, const std::vector<int> &layers);

// Percent in [0, 100] and what is being done; returns false to cancel.
using ProgressFn = std::function<bool(int, const QString &)>;

// Shares of the progress bar: copying in, the core's pipeline, copying out.
constexpr int kProgressCoreBegin = 5;
constexpr int kProgressCoreEnd = 95;

// Checks the meshes and the parameters, resolves the anchors and runs the pipeline.
// in:  request, source and target layers (copies; their boxes/normals get updated)
// out: result (cut, mapped, filled, report) and log lines (anchors, report) on success;
//      false and `error` (what went wrong and what to change) otherwise. Never throws.
bool MapLayers(const Request &request, InputLayer &source, InputLayer &target, const ProgressFn &progress,
               Result &result, QStringList &log, QString &error);

// Names of the new layers: "<source base name>_cut" etc.
QString OutputLabel(const QString &sourceLabel, const char *suffix);

// What the new layers carry, and whose textures.
struct OutputLayers {
  LayerComponents cut, mapped;  // the _filled layer carries what the cut does
  bool cutHasTargetTextures = false;  // the cut's texture names are the target's (else the source's)
};
OutputLayers OutputComponents(const Request &request, const InputLayer &source, const InputLayer &target,
                              const Report &report);

// "new layer spot_cut: 2930 vertices, 5856 faces", for the log.
QString LayerLine(const QString &label, const Mesh &mesh);

// The report's figures (core/report.h, FigureTable(): on_surface_rate, coverage,
// cut_boundary_loops, time_total_s, ...) by name, as numbers (counts as int, rates and
// shares in [0, 1], times in seconds), for flavours whose filters return values
// (pymeshlab's apply_filter returns them as a dict).
std::map<std::string, QVariant> ReportFigures(const Report &report);

}  // namespace eulermap::plugin
