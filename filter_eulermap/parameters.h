// The filter's parameters for every MeshLab flavour (DESIGN.md: adapter).
//
// The table itself is the core's (core/parameters.h: names, kinds, defaults, limits, help
// texts, in dialog and .mlx order); a flavour's shim turns each entry into its own
// RichParameter kind (rich_parameters.h) and reads the values back through ReadRequest().
// Nothing here knows MeshLab's plugin interface; only Qt and the core.
#pragma once

#include "core/parameters.h"
#include "core/pipeline.h"

#include <QString>
#include <QStringList>
#include <QVariant>

#include <functional>

namespace eulermap::plugin {

// Menu name, one-line description, long HTML description citing the paper.
QString FilterName();       // "Eulerian Surface Map"
QString FilterDescription();

// An entry's texts as Qt's.
inline QString Name(const Parameter &p) { return p.name; }
inline QString Label(const Parameter &p) { return p.label; }
inline QString Help(const Parameter &p) { return p.help; }
QStringList Choices(const Parameter &p);

// What the user asked for, independent of the MeshLab flavour.
struct Request {
  int sourceLayer = -1;  // the layer's number as the flavour names layers (2020.09: its
                         // position in the document, 2025.07: its id); -1: none
  int targetLayer = -1;
  Options options;        // transferColour and transferQuality both as asked; MapLayers keeps
                          // those the target has
  QString sourceAnchors;  // .pp file; empty: the .pp beside the source's file, if any
  QString targetAnchors;
  QString anchorPairs;    // "12:305, 40:77"; the other way to give anchors
};

// Reads every parameter of the filter (Parameter::inFilter) through `value` (called once
// per entry; Mesh parameters must come back as the layer's number, as in Request, -1 when
// none; Enum as the choice's index) into a Request.
Request ReadRequest(const std::function<QVariant(const Parameter &)> &value);

}  // namespace eulermap::plugin
