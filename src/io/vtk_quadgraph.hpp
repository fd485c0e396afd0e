#pragma once
/// @file vtk_quadgraph.hpp
/// @brief VTK views of a QuadGraph: the graph with per-node fields as a .vtu file (look inside the object
/// in ParaView: flux, kappa, mu, node kind), and surface simplification for the multi-resolution levels.
#include <map>
#include <string>
#include <vector>

#include <lucent/quadgraph/quad_graph.hpp>
#include <lucent/scene/mesh.hpp>

namespace lucent::io {

/// Nodes as points, graph edges as lines, each field (one value per node) as point data, plus "surface"
/// (1 for surface nodes). Written atomically; throws InputError naming the file on failure.
void writeQuadGraphVtu(const std::string& path, const quadgraph::QuadGraph& graph,
                       const std::map<std::string, std::vector<double>>& nodeFields);

/// Quadric decimation (vtkQuadricDecimation) to about `targetTriangles`; the result keeps the topology
/// only as far as VTK's decimation does, so callers tetrahedralize it and handle failure.
scene::TriangleMesh decimate(const scene::TriangleMesh& mesh, std::size_t targetTriangles);

}  // namespace lucent::io
