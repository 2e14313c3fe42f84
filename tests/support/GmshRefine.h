#pragma once
// An edit as Gmsh saves it, for the tests of edited meshes (tests/io, tests/pipelines).
#include <gmsh.h>

#include <filesystem>

namespace vesica::test {

// Gmsh's Mesh > Refine by splitting, saved over the mesh: its physical groups stay, its
// element data (thickness, fibers) do not.
inline void refine_in_gmsh(const std::filesystem::path& msh) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(msh.string());
  gmsh::model::mesh::refine();
  gmsh::write(msh.string());
  gmsh::finalize();
}

}  // namespace vesica::test
