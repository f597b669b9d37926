// Anchors for the filter: MeshLab picked-points files (.pp) matched by name, or
// vertex-index pairs, turned into the core's AnchorPair list (DESIGN.md: anchors).
//
// A .pp file is the XML that MeshLab's PickPoints editor writes:
//   <!DOCTYPE PickedPoints> <PickedPoints> <DocumentData>...</DocumentData>
//     <point x="..." y="..." z="..." active="1" name="nose"/> ... </PickedPoints>
// Points with active="0" are left out (the editor's "not present"). Qt's XML reader, no
// MeshLab code.
#pragma once

#include "core/pipeline.h"

#include <QString>

#include <vector>

namespace eulermap::plugin {

struct PickedPoint {
  QString name;
  Point3 position;
  bool active = true;
};

// Reads a .pp file. false (and `error` says why) when it cannot be read, is not a
// PickedPoints document, has a point without a name or with bad coordinates, or names
// two points alike.
bool ReadPickedPoints(const QString &path, std::vector<PickedPoint> &points, QString &error);

// The .pp file beside a mesh file, with the same base name: <dir>/<base>.pp, else the
// PickPoints editor's default <dir>/<base>_picked_points.pp. Empty when neither exists
// (or meshFile is empty, as for layers made by filters).
QString PickedPointsBeside(const QString &meshFile);

// Parses "12:305, 40:77" (pairs source:target; separated by commas, semicolons or
// blanks). false with `error` on anything else.
bool ParseAnchorPairs(const QString &text, std::vector<std::pair<int, int>> &pairs, QString &error);

// One layer as the anchor resolution sees it.
struct AnchorLayer {
  QString label;     // shown in messages
  QString fileName;  // the layer's file, for the default .pp; may be empty
  Mesh *mesh;        // the core copy (its bounding box and normals get updated)
};

struct AnchorSettings {
  QString sourceFile;  // explicit .pp files; empty: the default beside the layer's file
  QString targetFile;
  QString pairs;       // vertex-index pairs; exclusive with explicit files
  double maxDistance = 0.02;  // share of the mesh's bounding-box diagonal
};

// Finds the anchors the settings ask for and checks them: names that match, points
// within maxDistance of their surface, vertex indices in range. On success fills
// `anchors` (possibly empty) and `notes` (lines for the log: which files, which mode,
// anything skipped); on failure returns false with `error` saying what to change.
bool ResolveAnchors(const AnchorSettings &settings, const AnchorLayer &source, const AnchorLayer &target,
                    std::vector<AnchorPair> &anchors, QStringList &notes, QString &error);

}  // namespace eulermap::plugin
