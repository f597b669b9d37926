#include "filter_eulermap_2020.h"

#include "rich_parameters.h"
#include "run_on_layers.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QTimer>
#include <QWidget>

using namespace eulermap::plugin;

namespace {

// MeshLab 2020.09 keeps a layer's texture images in the GUI's OpenGL context and loads
// them only when it opens a file (MainWindow::updateTexture, with the current folder set
// to the file's; src/meshlab/mainwindow_RunTime.cpp): a filter's new layer would be drawn
// without them. So, once the filter has returned, ask the main window to load the layer's
// images from `folder`, the folder of the layer whose texture names it carries. Without
// a main window (meshlabserver) there is nothing to draw and nothing to do.
void LoadTexturesInGui(const MeshModel &layer, const QString &folder) {
  if (layer.cm.textures.empty() || !qobject_cast<QApplication *>(QCoreApplication::instance())) return;
  for (QWidget *window : QApplication::topLevelWidgets()) {
    if (!window->inherits("MainWindow")) continue;
    const int id = layer.id();
    QTimer::singleShot(0, window, [window, id, folder] {
      const QString current = QDir::currentPath();
      QDir::setCurrent(folder);
      QMetaObject::invokeMethod(window, "updateTexture", Qt::DirectConnection, Q_ARG(int, id));
      QDir::setCurrent(current);
    });
    return;
  }
}

// The document's layers, numbered by their position (as .mlx scripts and RichMesh do).
LayerDocument<MeshModel> Layers(MeshDocument &md) {
  LayerDocument<MeshModel> doc;
  for (int i = 0; i < md.size(); ++i) doc.layers.push_back(i);
  doc.layer = [&md](int i) { return md.meshList.at(i); };
  doc.add = [&md](const QString &label) { return md.addNewMesh("", label, false); };
  doc.copyTextureImages = [](MeshModel &to, const MeshModel &from) {
    LoadTexturesInGui(to, QFileInfo(from.fullName()).absolutePath());
  };
  return doc;
}

}  // namespace

FilterEulermapPlugin::FilterEulermapPlugin() {
  typeList << FP_EULERIAN_MAP;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterEulermapPlugin::pluginName() const { return "FilterEulermap"; }

QString FilterEulermapPlugin::filterName(FilterIDType) const { return FilterName(); }

QString FilterEulermapPlugin::filterInfo(FilterIDType) const { return FilterDescription(); }

// Remeshing: the filter makes new meshes whose connectivity and topology differ from
// both inputs (the cut source) and a remesh of the target with the source's
// connectivity (the mapped layer); texture transfer is optional and secondary.
MeshFilterInterface::FilterClass FilterEulermapPlugin::getClass(QAction *) { return MeshFilterInterface::Remeshing; }

// Two layers, chosen by the source_mesh / target_mesh parameters.
MeshFilterInterface::FILTER_ARITY FilterEulermapPlugin::filterArity(QAction *) const { return FIXED; }

int FilterEulermapPlugin::getPreConditions(QAction *) const { return MeshModel::MM_NONE; }

// The input layers are not changed; the results are new layers.
int FilterEulermapPlugin::postCondition(QAction *) const { return MeshModel::MM_NONE; }

void FilterEulermapPlugin::initParameterSet(QAction *, MeshDocument &md, RichParameterList &parameters) {
  const LayerDocument<MeshModel> layers = Layers(md);
  MeshModel *current = md.mm();
  MeshModel *other = current ? layers.layer(DefaultTargetLayer(md.meshList.indexOf(current), layers.layers)) : nullptr;
  MeshDocument *doc = current ? &md : nullptr;  // RichMesh asserts on a layer not in the document
  DeclareParameters(
      parameters,
      [&](const eulermap::Parameter &p) {
        return RichMesh(Name(p), Name(p) == eulermap::parameter::kSourceMesh ? current : other, doc, Label(p), Help(p));
      },
      [](const eulermap::Parameter &p) { return RichOpenFile(Name(p), QString(), Choices(p), Label(p), Help(p)); });
}

bool FilterEulermapPlugin::applyFilter(QAction *, MeshDocument &md, const RichParameterList &parameters,
                                       vcg::CallBackPos *cb) {
  const Request request =
      ReadParameters(parameters, [&](const eulermap::Parameter &p) { return md.meshList.indexOf(parameters.getMesh(Name(p))); });
  auto log = [this](const QString &line) { Log(GLLogStream::FILTER, line.toStdString()); };
  eulermap::Result result;
  QString error;
  if (RunOnLayers(request, Layers(md), MeshLabProgress(cb), log, result, error)) return true;
  // meshlabserver prints the log but not errorMessage: say it in both.
  errorMessage = error;
  Log(GLLogStream::WARNING, ("Eulerian Surface Map failed: " + error).toStdString());
  return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterEulermapPlugin)
