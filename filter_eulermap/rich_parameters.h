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
//      for a Mesh / OpenFile ParameterSpec
// out: every parameter of Parameters() added to list, in order, with its label and help
template <class List, class MakeMesh, class MakeOpenFile>
void DeclareParameters(List &list, MakeMesh &&mesh, MakeOpenFile &&openFile) {
  for (const ParameterSpec &p : Parameters()) {
    switch (p.kind) {
    case ParameterKind::Mesh: list.addParam(mesh(p)); break;
    case ParameterKind::Int: list.addParam(RichInt(p.name, p.defaultValue.toInt(), p.label, p.help)); break;
    case ParameterKind::Float: list.addParam(RichFloat(p.name, p.defaultValue.toDouble(), p.label, p.help)); break;
    case ParameterKind::Enum: list.addParam(RichEnum(p.name, p.defaultValue.toInt(), p.choices, p.label, p.help)); break;
    case ParameterKind::Bool: list.addParam(RichBool(p.name, p.defaultValue.toBool(), p.label, p.help)); break;
    case ParameterKind::OpenFile: list.addParam(openFile(p)); break;
    case ParameterKind::String: list.addParam(RichString(p.name, p.defaultValue.toString(), p.label, p.help)); break;
    }
  }
}

// in:  list, the parameter values the user gave; meshLayer(p): the number (as in Request)
//      of the layer a Mesh parameter names
// out: the Request
template <class List, class MeshLayer>
Request ReadParameters(const List &list, MeshLayer &&meshLayer) {
  return ReadRequest([&](const ParameterSpec &p) -> QVariant {
    switch (p.kind) {
    case ParameterKind::Mesh: return meshLayer(p);
    case ParameterKind::Int: return list.getInt(p.name);
    case ParameterKind::Float: return double(list.getFloat(p.name));
    case ParameterKind::Enum: return list.getEnum(p.name);
    case ParameterKind::Bool: return list.getBool(p.name);
    case ParameterKind::OpenFile: return list.getOpenFileName(p.name);
    case ParameterKind::String: return list.getString(p.name);
    }
    return {};
  });
}

}  // namespace eulermap::plugin
