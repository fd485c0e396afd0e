/// @file vtkLucentQuadGraph.h
/// @brief Adds the QuadGraph technique (the diffusion equation on a TetGen tetrahedralization's dual
/// graph, Wang et al. 2010) to vtkLucentFilter's techniques: SetTechnique("quadgraph") with its knobs
/// ("quadgraph.K", "quadgraph.levels", ...). A module of its own because TetGen is AGPL-3.0-or-later.
/// Loading the module's library registers the technique; Register() does so explicitly (idempotent).
#ifndef vtkLucentQuadGraph_h
#define vtkLucentQuadGraph_h

#include "LucentQuadGraphModule.h"
#include <vtkObject.h>

class LUCENTQUADGRAPH_EXPORT vtkLucentQuadGraph : public vtkObject {
 public:
  static vtkLucentQuadGraph* New();
  vtkTypeMacro(vtkLucentQuadGraph, vtkObject);

  /// Adds quadgraph to vtkLucentFilter::Techniques() once; true when the filter offers it.
  static bool Register();

 protected:
  vtkLucentQuadGraph() = default;
  ~vtkLucentQuadGraph() override = default;

 private:
  vtkLucentQuadGraph(const vtkLucentQuadGraph&) = delete;
  void operator=(const vtkLucentQuadGraph&) = delete;
};

#endif
