// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the meshes of Table 4 come from: two are generated, the fandisk is libcgal-demo's (or
// --fandisk FILE), the others are files NAME.off/.obj/.ply/.stl in a data folder. The default
// folder and the default fandisk are given by CMake (SIGMOID_NEIGHBORHOODS_APPLICATION_DATA,
// SIGMOID_NEIGHBORHOODS_FANDISK); nothing here knows a host path.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_DATA_H
#define SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_DATA_H

#include "table4_models.h"
#include "../tool_paths.h"

#include <Sigmoid_neighborhoods_readers/read_polygon_mesh.h>
#include "subdivided_polyhedra.h"

#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <filesystem>
#include <string>


namespace sigmoid_tool {

typedef SN::Oriented_point_set::Kernel Denoise_kernel;
typedef Denoise_kernel::Point_3 Denoise_point;
typedef Denoise_kernel::Vector_3 Denoise_vector;
typedef CGAL::Surface_mesh<Denoise_point> Denoise_mesh;

constexpr unsigned int GENERATED_CUBE_SUBDIVISIONS = 18;       // 1,946 vertices
constexpr unsigned int GENERATED_OCTAHEDRON_SUBDIVISIONS = 64; // 16,386 vertices

// The folder of the application models: $SIGMOID_NEIGHBORHOODS_APPLICATION_DATA, else CMake's.
inline std::string default_application_data()
{
  if(const char* env = std::getenv("SIGMOID_NEIGHBORHOODS_APPLICATION_DATA"))
    return env;
  return std::filesystem::path(tool_paths::application_data()).lexically_normal().string();
}

// The mesh of a model name, or false and the reason it is absent. Models given as files have the
// file's name. A file that cannot be read throws SN::Input_error.
inline bool load_denoise_mesh(const std::string& name, const std::string& data_dir, const std::string& fandisk,
                              Denoise_mesh& mesh, std::string& source, std::string& absent)
{
  namespace fs = std::filesystem;
  if(name == "cube")
  {
    SN::make_subdivided_cube(GENERATED_CUBE_SUBDIVISIONS, mesh);
    source = "generated: make_subdivided_cube(" + std::to_string(GENERATED_CUBE_SUBDIVISIONS) + ")";
    return true;
  }
  if(name == "octahedron")
  {
    SN::make_subdivided_octahedron(GENERATED_OCTAHEDRON_SUBDIVISIONS, mesh);
    source = "generated: make_subdivided_octahedron(" + std::to_string(GENERATED_OCTAHEDRON_SUBDIVISIONS) + ")";
    return true;
  }
  std::error_code ec;
  if(name == "fandisk")
  {
    if(!fandisk.empty())
    {
      SN::read_polygon_mesh(fandisk, mesh);
      source = fandisk;
      return true;
    }
    // libcgal-demo's data/meshes/fandisk.off, as CMake extracted it
    const std::string cgal_fandisk = tool_paths::default_fandisk();
    if(cgal_fandisk.empty() || !fs::exists(cgal_fandisk, ec))
    {
      absent = "not found: give --fandisk FILE (data/meshes/fandisk.off of libcgal-demo's data archive)";
      return false;
    }
    SN::read_polygon_mesh(cgal_fandisk, mesh);
    source = "libcgal-demo: " + cgal_fandisk;
    return true;
  }
  if(find_table4_model(name) != nullptr)
  {
    for(const char* ext : {".off", ".obj", ".ply", ".stl"})
    {
      const fs::path file = fs::path(data_dir) / (name + ext);
      if(fs::exists(file, ec))
      {
        SN::read_polygon_mesh(file.string(), mesh);
        source = file.string();
        return true;
      }
    }
    absent = "absent: no " + name + ".off/.obj/.ply/.stl in " + data_dir;
    return false;
  }
  SN::read_polygon_mesh(name, mesh); // a file given by the user
  source = name;
  return true;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_EXPERIMENTS_TABLE4_DATA_H
