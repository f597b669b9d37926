#include "parameters.h"

#include <cctype>
#include <cmath>
#include <sstream>

namespace eulermap {

namespace {

using K = ParameterKind;

std::string Number(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

std::string XmlEscaped(const std::string &text) {
  std::string out;
  for (char c : text)
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  return out;
}

const char *MlxType(ParameterKind kind) {
  switch (kind) {
  case K::Mesh: return "RichMesh";
  case K::Int: return "RichInt";
  case K::Float: return "RichFloat";
  case K::Enum: return "RichEnum";
  case K::Bool: return "RichBool";
  case K::OpenFile: return "RichOpenFile";
  case K::String: return "RichString";
  }
  return "";
}

} // namespace

bool Parameter::InRange(double value) const {
  return std::isfinite(value) && (lowIncluded ? value >= low : value > low) && value <= high;
}

void Parameter::Check(const Options &options) const {
  if (!get || (kind != K::Int && kind != K::Float)) return;
  const double value = get(options);
  if (!InRange(value))
    throw Error(std::string(name) + " " + Number(value) + " is out of range: give a number " +
                (lowIncluded ? "from " : "above ") + Number(low) + (lowIncluded ? " to " : " up to ") + Number(high) +
                " (" + meaning + "; " + Number(Default()) + " is the default)");
}

// Every run costs (grid nodes) x (steps) velocity solves; the memory a grid needs is
// checked against what the process may have (memory.h); the limits bound the rest.
const std::vector<Parameter> &Parameters() {
  static const std::vector<Parameter> table = {
      {parameter::kSourceMesh, K::Mesh, "Source mesh",
       "The surface M0 to map from (default: the current layer). It is left untouched; the results "
       "are new layers named after it (sphere.ply gives sphere_cut, sphere_mapped and, with "
       "fill_holes, sphere_filled)."},
      {parameter::kTargetMesh, K::Mesh, "Target mesh",
       "The surface M1 to map onto. It may have a different genus or number of components than the "
       "source; it must be another layer than the source. It is left untouched."},
      {"grid_resolution", K::Int, "Grid resolution",
       "Cells on the longest side of the padded box holding both surfaces. The signed distance "
       "fields, the morph and the velocity fields live on this grid: finer grids follow thin "
       "parts and small handles better, at a cubic cost in memory and time. Features thinner "
       "than about two cells are lost. A grid too large for memory is refused with a message.",
       {},
       [](const Options &o) { return double(o.gridResolution); },
       [](Options &o, double v) { o.gridResolution = int(v); },
       8, 4096, true, "cells on the longest axis"},
      {"steps", K::Int, "Time steps",
       "Number of steps from t = 0 (source) to t = 1 (target). Each step solves one velocity "
       "field (paper, Eqs. 2-6) and moves every tracked point along it (Eq. 7). More steps: "
       "smaller moves per step and fewer points lost on fast-changing parts.",
       {},
       [](const Options &o) { return double(o.steps); },
       [](Options &o, double v) { o.steps = int(v); },
       1, 1000, true, "time steps; more only slows"},
      {"alpha", K::Float, "Smoothness (alpha)",
       "Weight of the smoothness term alpha |grad V|^2 of the velocity energy (paper, Eq. 2). "
       "Larger values give smoother, less distorted maps but let points drift further from the "
       "moving surface, which the pull-back then corrects.",
       {},
       [](const Options &o) { return o.alpha; },
       [](Options &o, double v) { o.alpha = v; },
       0, 1e6, false, "the smoothness weight"},
      {"hole_radius", K::Float, "Hole radius (cells)",
       "Radius, in grid cells, of the sphere around a topology change of the moving surface inside "
       "which source faces are cut away (paper, Sec. 3). Larger radii "
       "cut bigger, cleaner holes.",
       {},
       [](const Options &o) { return o.holeRadius; },
       [](Options &o, double v) { o.holeRadius = v; },
       0, 16, false, "in grid cells: a larger sphere cuts whole parts away"},
      {"align", K::Enum, "Alignment",
       "How the target is placed in the source's frame when no anchors are given: 'none' keeps "
       "it where it is; 'centre-and-scale' moves its centroid onto the source's and scales its "
       "bounding-box diagonal to the source's, and where that map fails its own checks (the "
       "log's warnings) tries 'overlap' as well and keeps the better map; 'overlap' moves and "
       "scales it further (no rotation) so that the two insides overlap most, which spares the "
       "morph parts that grow from nothing and handles that open and close again. With "
       "anchors, the similarity fitted to them is used instead. The map always lands on the "
       "target where it really is.",
       {"none", "centre-and-scale", "overlap"},
       [](const Options &o) { return double(int(o.align)); },
       [](Options &o, double v) { o.align = Align(int(v)); }},
      {parameter::kSourceAnchors, K::OpenFile, "Source anchors (.pp)",
       "MeshLab picked-points file (Edit > PickPoints, saved as .pp) with named anchor points on "
       "the source. Empty: the .pp beside the source's file with the same base name "
       "(spot.obj -> spot.pp or spot_picked_points.pp), when there is one. Points are matched "
       "to the target's by name; a name on one side only, or a point farther than 2% of the "
       "bounding-box diagonal from its surface, is an error. 1-3 anchors fit a similarity; 4 or "
       "more non-coplanar anchors also steer the morph (ARAP + thin-plate warp).",
       {"*.pp"}},
      {parameter::kTargetAnchors, K::OpenFile, "Target anchors (.pp)",
       "MeshLab picked-points file with the target's anchor points, named as in the source's. "
       "Empty: the .pp beside the target's file, when there is one.",
       {"*.pp"}},
      {parameter::kAnchorPairs, K::String, "Anchor vertex pairs",
       "Anchors as pairs of vertex indices, source:target, separated by commas, e.g. "
       "'12:305, 40:77'. Used instead of .pp files when not empty (give one or the other)."},
      {"fill_holes", K::Bool, "Fill holes",
       "Also make the _filled layer: the cut source with the holes left by surgery closed again.",
       {},
       [](const Options &o) { return double(o.fillHoles); },
       [](Options &o, double v) { o.fillHoles = v != 0; }},
      {"transfer_texture", K::Bool, "Transfer texture",
       "When the target has texture coordinates (per wedge or per vertex), pull them back onto "
       "the _cut layer, per wedge, read at each vertex's image on the target, together with the "
       "target's texture file names, so the source shows the target's texture (paper, Sec. 4.1). "
       "A face never mixes two charts of the target's texture. The _mapped layer always keeps "
       "the source's own texture coordinates and texture: the source's texture on the target's "
       "shape.",
       {},
       [](const Options &o) { return double(o.transferTexture); },
       [](Options &o, double v) { o.transferTexture = v != 0; }},
      {"transfer_color_quality", K::Bool, "Transfer colour and quality",
       "Also pull the target's per-vertex colour and quality, those it has, onto the _cut layer "
       "through the map (interpolated at each vertex's image). The _cut layer's vertex quality "
       "then is the target's instead of the local distortion.",
       {},
       [](const Options &o) { return double(o.transferColour || o.transferQuality); },
       [](Options &o, double v) { o.transferColour = o.transferQuality = v != 0; }},
      // Set by the core's callers only (the tests, the benchmark).
      {"anchor_weight", K::Float, "Anchor weight", "beta at an anchor: the pull of its motion on V (velocity.h)",
       {},
       [](const Options &o) { return o.anchorWeight; },
       [](Options &o, double v) { o.anchorWeight = v; },
       0, 1e6, true, "0 is the paper's Eq. 2", false},
      {"anchor_radius", K::Float, "Anchor radius", "reach of an anchor's pull on V, in grid cells",
       {},
       [](const Options &o) { return o.anchorRadius; },
       [](Options &o, double v) { o.anchorRadius = v; },
       0, 64, false, "in grid cells", false},
      {"tolerance", K::Float, "Tolerance", "relative residual that ends a velocity solve",
       {},
       [](const Options &o) { return o.tolerance; },
       [](Options &o, double v) { o.tolerance = v; },
       0, 0.5, false, "relative residual of a velocity solve", false},
      {"max_iterations", K::Int, "Iterations", "most iterations of one velocity solve",
       {},
       [](const Options &o) { return double(o.maxIterations); },
       [](Options &o, double v) { o.maxIterations = int(v); },
       1, 100000, true, "per velocity solve", false},
      {"threads", K::Int, "Threads", "threads of each parallel loop (parallel.h); 0: OMP_NUM_THREADS, else the machine's cores",
       {},
       [](const Options &o) { return double(o.threads); },
       [](Options &o, double v) { o.threads = int(v); },
       0, 1024, true, "0 uses OMP_NUM_THREADS, else the machine's cores", false},
  };
  return table;
}

const Parameter &FindParameter(const std::string &name) {
  for (const Parameter &p : Parameters())
    if (name == p.name) return p;
  throw Error("no parameter named " + name);
}

std::string ValueText(const Parameter &p, double value) {
  if (p.kind == K::Bool) return value != 0 ? "true" : "false";
  return Number(value);
}

std::string MlxFilter(const std::map<std::string, std::string> &values) {
  std::ostringstream o;
  o << " <filter name=\"" << kFilterName << "\">\n";
  for (const Parameter &p : Parameters()) {
    if (!p.inFilter) continue;
    const auto given = values.find(p.name);
    const std::string value = given != values.end()              ? given->second
                              : p.name == std::string(parameter::kTargetMesh) ? "1"
                              : p.kind == K::Mesh                ? "0"
                              : p.get                            ? ValueText(p, p.Default())
                                                                 : "";
    o << "  <Param type=\"" << MlxType(p.kind) << "\" name=\"" << p.name << "\" value=\"" << XmlEscaped(value) << "\"";
    if (p.kind == K::Enum) {
      o << " enum_cardinality=\"" << p.choices.size() << "\"";
      for (std::size_t n = 0; n < p.choices.size(); ++n) o << " enum_val" << n << "=\"" << p.choices[n] << "\"";
    } else if (p.kind == K::OpenFile) {
      o << " exts_cardinality=\"" << p.choices.size() << "\"";
      for (std::size_t n = 0; n < p.choices.size(); ++n) o << " exts_val" << n << "=\"" << p.choices[n] << "\"";
    }
    o << " description=\"" << XmlEscaped(p.label) << "\"/>\n";
  }
  o << " </filter>\n";
  for (const auto &[name, value] : values)
    if (!FindParameter(name).inFilter) throw Error(name + " is not a parameter of the filter");
  return o.str();
}

namespace {
// The first sentence of a help text: up to a full stop before a capital letter.
std::string FirstSentence(const std::string &help) {
  for (std::size_t n = 0; n + 2 < help.size(); ++n)
    if (help[n] == '.' && help[n + 1] == ' ' && std::isupper(static_cast<unsigned char>(help[n + 2])))
      return help.substr(0, n + 1);
  return help;
}
} // namespace

std::string ParametersMarkdown() {
  std::ostringstream o;
  for (const Parameter &p : Parameters()) {
    if (!p.inFilter) continue;
    o << "- `" << p.name << "`";
    std::string facts;
    if (p.kind == K::Enum) {
      for (const std::string &c : p.choices) facts += (facts.empty() ? "" : " / ") + c;
      facts += ", default " + p.choices[std::size_t(p.Default())];
    } else if (p.kind == K::Int || p.kind == K::Float) {
      facts = (p.lowIncluded ? "" : "above ") + Number(p.low) + (p.lowIncluded ? "-" : " up to ") + Number(p.high) +
              ", default " + ValueText(p, p.Default());
    } else if (p.get) {
      facts = "default " + ValueText(p, p.Default());
    }
    if (!facts.empty()) o << " (" << facts << ")";
    o << ": " << FirstSentence(p.help) << "\n";
  }
  return o.str();
}

} // namespace eulermap
