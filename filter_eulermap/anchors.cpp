#include "anchors.h"

#include "core/closest.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSet>
#include <QXmlStreamReader>

#include <map>

namespace eulermap::plugin {

namespace {

bool ReadCoordinate(const QXmlStreamAttributes &a, const char *axis, double &out) {
  bool ok = false;
  out = a.value(axis).toString().toDouble(&ok);
  return ok;
}

QString Name(const QString &path) { return QFileInfo(path).fileName(); }

// Active points of a .pp by name; inactive names in `skipped`.
bool ReadActive(const QString &path, const char *role, std::map<QString, Point3> &points, QSet<QString> &skipped,
                QString &error) {
  std::vector<PickedPoint> all;
  QString why;
  if (!ReadPickedPoints(path, all, why)) {
    error = QString("%1 anchors: %2").arg(role, why);
    return false;
  }
  for (const PickedPoint &p : all) {
    if (p.active) points[p.name] = p.position;
    else skipped.insert(p.name);
  }
  return true;
}

// Distance of p from the surface of `mesh`, as a share of its bounding-box diagonal.
double RelativeDistance(const ClosestPoint &closest, const Mesh &mesh, const Point3 &p, double &absolute) {
  absolute = closest.Query(p).distance;
  const double diag = mesh.bbox.Diag();
  return diag > 0 ? absolute / diag : 0;
}

}  // namespace

bool ReadPickedPoints(const QString &path, std::vector<PickedPoint> &points, QString &error) {
  points.clear();
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    error = QString("cannot open '%1' (%2); give an existing MeshLab picked-points (.pp) file, or leave "
                    "the parameter empty")
                .arg(path, file.errorString());
    return false;
  }
  QXmlStreamReader xml(&file);
  bool rootSeen = false;
  QSet<QString> names;
  while (!xml.atEnd()) {
    if (xml.readNext() != QXmlStreamReader::StartElement) continue;
    if (!rootSeen) {
      if (xml.name() != QLatin1String("PickedPoints")) {
        error = QString("'%1' is not a MeshLab picked-points file (its root element is <%2>, not "
                        "<PickedPoints>)")
                    .arg(path, xml.name().toString());
        return false;
      }
      rootSeen = true;
      continue;
    }
    if (xml.name() != QLatin1String("point")) continue;
    const QXmlStreamAttributes a = xml.attributes();
    PickedPoint p;
    p.name = a.value("name").toString().trimmed();
    double x, y, z;
    const int line = int(xml.lineNumber());
    if (p.name.isEmpty()) {
      error = QString("'%1', line %2: a point without a name; anchors are matched by name").arg(path).arg(line);
      return false;
    }
    if (!ReadCoordinate(a, "x", x) || !ReadCoordinate(a, "y", y) || !ReadCoordinate(a, "z", z)) {
      error = QString("'%1', line %2: point '%3' lacks numeric x, y, z").arg(path).arg(line).arg(p.name);
      return false;
    }
    if (names.contains(p.name)) {
      error = QString("'%1': two points are named '%2'; give each anchor its own name").arg(path, p.name);
      return false;
    }
    names.insert(p.name);
    p.position = Point3(x, y, z);
    p.active = a.value("active").toString() != QLatin1String("0");
    points.push_back(p);
  }
  if (xml.hasError()) {
    error = QString("'%1' is not well-formed XML (line %2: %3)").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return false;
  }
  if (!rootSeen) {
    error = QString("'%1' is empty, not a MeshLab picked-points file").arg(path);
    return false;
  }
  return true;
}

QString PickedPointsBeside(const QString &meshFile) {
  if (meshFile.isEmpty()) return {};
  const QFileInfo fi(meshFile);
  for (const QString &candidate : {fi.completeBaseName() + ".pp", fi.completeBaseName() + "_picked_points.pp"}) {
    const QFileInfo pp(fi.dir(), candidate);
    if (pp.isFile()) return pp.absoluteFilePath();
  }
  return {};
}

bool ParseAnchorPairs(const QString &text, std::vector<std::pair<int, int>> &pairs, QString &error) {
  pairs.clear();
  static const QRegularExpression separators("[,;\\s]+");
  static const QRegularExpression pair("^(\\d+):(\\d+)$");
  for (const QString &token : text.split(separators, Qt::SkipEmptyParts)) {
    const QRegularExpressionMatch m = pair.match(token);
    bool ok1 = false, ok2 = false;
    const int s = m.hasMatch() ? m.captured(1).toInt(&ok1) : 0, t = m.hasMatch() ? m.captured(2).toInt(&ok2) : 0;
    if (!ok1 || !ok2) {
      error = QString("anchor_pairs: '%1' is not a pair of vertex indices; write source:target pairs "
                      "separated by commas, e.g. '12:305, 40:77'")
                  .arg(token);
      return false;
    }
    pairs.emplace_back(s, t);
  }
  if (pairs.empty()) {
    error = QString("anchor_pairs: '%1' holds no pair of vertex indices; write source:target pairs separated by "
                    "commas, e.g. '12:305, 40:77', or leave it empty for no anchors").arg(text);
    return false;
  }
  return true;
}

bool ResolveAnchors(const AnchorSettings &settings, const AnchorLayer &source, const AnchorLayer &target,
                    std::vector<AnchorPair> &anchors, QStringList &notes, QString &error) {
  anchors.clear();
  const bool pairsGiven = !settings.pairs.isEmpty();
  const bool filesGiven = !settings.sourceFile.isEmpty() || !settings.targetFile.isEmpty();
  if (pairsGiven && filesGiven) {
    error = "anchors given twice: clear either anchor_pairs or source_anchors/target_anchors";
    return false;
  }

  if (pairsGiven) {
    std::vector<std::pair<int, int>> pairs;
    if (!ParseAnchorPairs(settings.pairs, pairs, error)) return false;
    for (const auto &[s, t] : pairs) {
      const int sn = int(source.mesh->vert.size()), tn = int(target.mesh->vert.size());
      if (s >= sn || t >= tn) {
        error = QString("anchor_pairs: %1:%2 is out of range; '%3' has vertices 0..%4 and '%5' has 0..%6")
                    .arg(s).arg(t).arg(source.label).arg(sn - 1).arg(target.label).arg(tn - 1);
        return false;
      }
      anchors.push_back({source.mesh->vert[s].cP(), target.mesh->vert[t].cP(),
                         QString("%1:%2").arg(s).arg(t).toStdString()});
    }
    notes << QString("anchors: %1 vertex pairs from anchor_pairs").arg(anchors.size());
    return true;
  }

  const QString sourceFile = settings.sourceFile.isEmpty() ? PickedPointsBeside(source.fileName) : settings.sourceFile;
  const QString targetFile = settings.targetFile.isEmpty() ? PickedPointsBeside(target.fileName) : settings.targetFile;
  if (sourceFile.isEmpty() && targetFile.isEmpty()) {
    notes << "anchors: none (no anchor_pairs, no .pp files given or found beside the layers' files)";
    return true;
  }
  if (sourceFile.isEmpty() || targetFile.isEmpty()) {
    const bool sourceMissing = sourceFile.isEmpty();
    const QString have = sourceMissing ? targetFile : sourceFile;
    if (!settings.sourceFile.isEmpty() || !settings.targetFile.isEmpty()) {
      error = QString("%1 anchors are given (%2) but no .pp file was found for the %3 '%4': set %5 too")
                  .arg(sourceMissing ? "target" : "source", Name(have), sourceMissing ? "source" : "target",
                       sourceMissing ? source.label : target.label,
                       sourceMissing ? "source_anchors" : "target_anchors");
      return false;
    }
    notes << QString("warning: anchors not used: %1 lies beside the %2 but the %3 '%4' has no .pp file")
                 .arg(Name(have), sourceMissing ? "target" : "source", sourceMissing ? "source" : "target",
                      sourceMissing ? source.label : target.label);
    return true;
  }

  std::map<QString, Point3> a, b;
  QSet<QString> skipped;
  if (!ReadActive(sourceFile, "source", a, skipped, error) || !ReadActive(targetFile, "target", b, skipped, error))
    return false;
  for (const QString &name : skipped) {
    a.erase(name);
    b.erase(name);
  }
  QStringList onlySource, onlyTarget;
  for (const auto &[name, p] : a)
    if (!b.count(name)) onlySource << "'" + name + "'";
  for (const auto &[name, p] : b)
    if (!a.count(name)) onlyTarget << "'" + name + "'";
  if (!onlySource.isEmpty() || !onlyTarget.isEmpty()) {
    QStringList parts;
    if (!onlySource.isEmpty()) parts << QString("%1 only in %2").arg(onlySource.join(", "), Name(sourceFile));
    if (!onlyTarget.isEmpty()) parts << QString("%1 only in %2").arg(onlyTarget.join(", "), Name(targetFile));
    error = QString("anchor names do not match: %1. Give both files the same point names, or mark a "
                    "point inactive (active=\"0\") to leave it out")
                .arg(parts.join("; "));
    return false;
  }

  // Every anchor must lie on (near) its own surface.
  ClosestPoint onSource(*source.mesh), onTarget(*target.mesh);
  for (const auto &[name, p] : a) {
    const Point3 &q = b.at(name);
    struct Side { const Point3 &point; const ClosestPoint &closest; const AnchorLayer &layer; const QString &file; };
    for (const Side &side : {Side{p, onSource, source, sourceFile}, Side{q, onTarget, target, targetFile}}) {
      double absolute = 0;
      const double relative = RelativeDistance(side.closest, *side.layer.mesh, side.point, absolute);
      if (relative > settings.maxDistance) {
        error = QString("anchor '%1' in %2 lies %3 from '%4' (%5% of its bounding-box diagonal; at most "
                        "%6% is accepted): was it picked on another mesh? Pick it again on this layer or "
                        "give the right .pp file")
                    .arg(name, Name(side.file)).arg(absolute, 0, 'g', 4).arg(side.layer.label)
                    .arg(100 * relative, 0, 'f', 1).arg(100 * settings.maxDistance, 0, 'g', 3);
        return false;
      }
    }
    anchors.push_back({p, q, name.toStdString()});
  }
  notes << QString("anchors: %1 named pairs from %2 and %3").arg(anchors.size()).arg(sourceFile, targetFile);
  if (!skipped.isEmpty()) {
    QStringList s = skipped.values();
    s.sort();
    notes << QString("anchors left out (inactive): %1").arg(s.join(", "));
  }
  return true;
}

}  // namespace eulermap::plugin
