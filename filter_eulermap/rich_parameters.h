// The filter's parameters (parameters.h) on a MeshLab parameter list, for every flavour.
//
// RichInt, RichFloat, RichEnum, RichBool and RichString, and the list's getters, have the
// same names and arguments in MeshLab 2020.09 and 2025.07; the mesh and open-file
// parameters differ (RichMesh's arguments, RichOpenFile / RichFileOpen, how a chosen mesh
// is read back), so the shim passes those in. Like run_on_layers.h, this header is
// included after the flavour's own MeshLab headers, whose classes it names.
#pragma once

#include "parameters.h"

namespace eulermap::plugin {

// in:  list, a MeshLab parameter list; mesh(p), openFile(p): the flavour's Rich parameter
//      for a Mesh / OpenFile entry of the table
// out: every parameter of the filter (Parameter::inFilter) added to list, in order, with its
//      default, label and help
template <class List, class MakeMesh, class MakeOpenFile>
void DeclareParameters(List &list, MakeMesh &&mesh, MakeOpenFile &&openFile) {
  for (const Parameter &p : Parameters()) {
    if (!p.inFilter) continue;
    switch (p.kind) {
    case ParameterKind::Mesh: list.addParam(mesh(p)); break;
    case ParameterKind::Int: list.addParam(RichInt(Name(p), int(p.Default()), Label(p), Help(p))); break;
    case ParameterKind::Float: list.addParam(RichFloat(Name(p), p.Default(), Label(p), Help(p))); break;
    case ParameterKind::Enum: list.addParam(RichEnum(Name(p), int(p.Default()), Choices(p), Label(p), Help(p))); break;
    case ParameterKind::Bool: list.addParam(RichBool(Name(p), p.Default() != 0, Label(p), Help(p))); break;
    case ParameterKind::OpenFile: list.addParam(openFile(p)); break;
    case ParameterKind::String: list.addParam(RichString(Name(p), QString(), Label(p), Help(p))); break;
    }
  }
}

// in:  list, the parameter values the user gave; meshLayer(p): the number (as in Request)
//      of the layer a Mesh parameter names
// out: the Request
template <class List, class MeshLayer>
Request ReadParameters(const List &list, MeshLayer &&meshLayer) {
  return ReadRequest([&](const Parameter &p) -> QVariant {
    const QString name = Name(p);
    switch (p.kind) {
    case ParameterKind::Mesh: return meshLayer(p);
    case ParameterKind::Int: return list.getInt(name);
    case ParameterKind::Float: return double(list.getFloat(name));
    case ParameterKind::Enum: return list.getEnum(name);
    case ParameterKind::Bool: return double(list.getBool(name));
    case ParameterKind::OpenFile: return list.getOpenFileName(name);
    case ParameterKind::String: return list.getString(name);
    }
    return {};
  });
}

}  // namespace eulermap::plugin
