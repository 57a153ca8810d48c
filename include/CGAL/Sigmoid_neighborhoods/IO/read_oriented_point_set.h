// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_ORIENTED_POINT_SET_H
#define CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_ORIENTED_POINT_SET_H

#include <CGAL/Sigmoid_neighborhoods/internal/K_neighbor_query.h>
#include <CGAL/Sigmoid_neighborhoods/internal/mesh_points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  a point set with oriented unit normals read from a file, and how it was obtained (SPEC §1).
  Returned by `read_oriented_point_set()`; its `points` and `normals` go to
  `compute_optimal_sigmoid_neighborhoods()` with `CGAL::make_property_map()` maps over the indices
  `0, ..., points.size() - 1`, as the command-line tool does.
*/
struct Oriented_point_set
{
  /// the kernel of the points and normals
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  /// the point type
  typedef Kernel::Point_3 Point_3;
  /// the normal type
  typedef Kernel::Vector_3 Vector_3;

  std::vector<Point_3> points;   ///< distinct points, in input order
  std::vector<Vector_3> normals; ///< unit normals, one per point
  bool is_mesh = false;                 ///< read from faces; normals are vertex normals
  bool normals_estimated = false;       ///< the file had no normals: jet fitting + MST orientation
  std::size_t input_vertices = 0;       ///< vertices or points in the file
  std::size_t merged_duplicates = 0;    ///< merged into an earlier point at the same position
  std::size_t dropped_vertices = 0;     ///< mesh vertices without a face or with an undefined normal
  std::size_t unoriented_normals = 0;   ///< estimated normals the MST could not reach (kept as estimated)
};

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  the error thrown by `read_oriented_point_set()`: its `what()` is one line for a person.
*/
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

inline std::string lower_extension(const std::string& filename)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = filename.substr(dot + 1);
  for(char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

inline bool is_finite(const Oriented_point_set::Point_3& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

// Beyond this magnitude, squared distances overflow a double.
constexpr double LARGEST_COORDINATE = 1e150;

inline void check_coordinates(const Oriented_point_set::Point_3& p, const char* what, std::size_t i)
{
  if(!is_finite(p))
    throw Input_error(std::string(what) + " " + std::to_string(i) + " has a non-finite coordinate");
  if(std::abs(p.x()) > LARGEST_COORDINATE || std::abs(p.y()) > LARGEST_COORDINATE ||
     std::abs(p.z()) > LARGEST_COORDINATE)
    throw Input_error(std::string(what) + " " + std::to_string(i) +
                      " has a coordinate beyond 1e150, where squared distances overflow");
}

// CGAL's readers explain a failure on std::cerr; keep the explanation for our one-line message.
class Captured_cerr
{
public:
  Captured_cerr() : m_old(std::cerr.rdbuf(m_buffer.rdbuf())) {}
  ~Captured_cerr() { std::cerr.rdbuf(m_old); }
  std::string first_line() const
  {
    std::string text = m_buffer.str();
    const std::size_t end = text.find('\n');
    text = text.substr(0, end);
    if(text.rfind("Error: ", 0) == 0)
      text = text.substr(7);
    return text;
  }

private:
  std::ostringstream m_buffer;
  std::streambuf* m_old;
};

// `x y z` or `x y z nx ny nz` per line; `#` starts a comment. Strict, with line numbers.
inline void read_xyz(const std::string& filename, std::vector<Oriented_point_set::Point_3>& points,
                     std::vector<Oriented_point_set::Vector_3>& normals, bool& has_normals)
{
  std::ifstream in(filename);
  std::string line;
  std::size_t line_number = 0, columns = 0;
  while(std::getline(in, line))
  {
    ++line_number;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos)
      line.erase(hash);
    std::istringstream tokens(line);
    std::vector<double> values;
    std::string token;
    while(tokens >> token)
    {
      const char* begin = token.c_str();
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if(end == begin || *end != '\0')
        throw Input_error("line " + std::to_string(line_number) + ": '" + token + "' is not a number");
      if(!std::isfinite(v))
        throw Input_error("line " + std::to_string(line_number) + ": non-finite value '" + token + "'");
      values.push_back(v);
    }
    if(values.empty())
      continue;
    if(values.size() != 3 && values.size() != 6)
      throw Input_error("line " + std::to_string(line_number) + ": expected 3 (x y z) or 6 (x y z nx ny nz) numbers, got " +
                        std::to_string(values.size()));
    if(columns == 0)
      columns = values.size();
    else if(values.size() != columns)
      throw Input_error("line " + std::to_string(line_number) + ": " + std::to_string(values.size()) +
                        " numbers where earlier lines have " + std::to_string(columns));
    points.emplace_back(values[0], values[1], values[2]);
    if(columns == 6)
      normals.emplace_back(values[3], values[4], values[5]);
  }
  if(in.bad())
    throw Input_error("read error");
  has_normals = (columns == 6);
}

// CGAL's readers trust the counts of a header: `read_OFF()` resizes its vectors to them and
// `read_PLY()` loops over them, so a header of a few bytes could ask for gigabytes or hours (found
// by fuzzing). Every vertex, face or PLY element item takes at least one byte of the file.
inline void check_header_count(std::uintmax_t count, std::uintmax_t file_size, const std::string& what)
{
  if(count > file_size)
    throw Input_error("the header announces " + std::to_string(count) + " " + what + ", more than a file of " +
                      std::to_string(file_size) + " bytes can hold");
}

// The polygon soup of an OFF file: the loop of CGAL 5.5's `IO::read_OFF()` over CGAL's scanner,
// less what it does unchecked (found by fuzzing): it resizes to the counts of the header and of each
// face as they come (bounded here by the file size), and in ASCII it takes colors and texture
// coordinates at positions of the line that a short line does not have (a heap read out of bounds;
// they are not used here, so not read: the scanner has read the whole line already).
inline bool read_off_soup(const std::string& filename, std::uintmax_t file_size,
                          std::vector<Oriented_point_set::Point_3>& points,
                          std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream is(filename);
  CGAL::File_scanner_OFF scanner(is);
  if(is.fail())
    return false;
  const std::size_t vertices = scanner.size_of_vertices(), faces = scanner.size_of_facets();
  check_header_count(vertices, file_size, "vertices");
  check_header_count(faces, file_size - vertices, "faces after the vertices");
  points.resize(vertices);
  polygons.resize(faces);
  for(std::size_t i = 0; i < vertices; ++i)
  {
    double x = 0., y = 0., z = 0., w = 1.;
    scanner.scan_vertex(x, y, z, w);
    points[i] = Oriented_point_set::Point_3(x / w, y / w, z / w); // w = 0: non-finite, refused later
    if(scanner.binary() && scanner.has_normals())
    {
      double nx, ny, nz;
      scanner.scan_normal(nx, ny, nz);
    }
    if(scanner.binary() && scanner.has_textures())
    {
      double u, v, t;
      scanner.scan_texture(u, v, t);
    }
    if(!is.good())
      return false;
  }
  for(std::size_t i = 0; i < faces; ++i)
  {
    std::size_t corners = std::size_t(-1);
    scanner.scan_facet(corners, i);
    if((!is.eof() && !is.good()) || corners == std::size_t(-1))
      return false;
    check_header_count(corners, file_size, "corners of face " + std::to_string(i));
    polygons[i].resize(corners);
    for(std::size_t j = 0; j < corners; ++j)
    {
      std::size_t id = 0;
      scanner.scan_facet_vertex_index(id, j + 1, i);
      if(!is || id >= vertices)
        return false;
      polygons[i][j] = id;
    }
  }
  return !is.fail();
}

// Besides the counts, header contents that CGAL 5.5's PLY reader does not check (crashes, found by
// fuzzing): a `property` line before any `element` line (it takes the back() of an empty vector),
// and vertex properties of another type than it reads them as (it dereferences a failed
// dynamic_cast): `x y z` as float or double, and, in a point set (no faces), which CGAL reads all as
// float when one of `x y z` is float, `nx ny nz` as float then; a point set also looks its other
// properties up by name, cut at a NUL byte, so vertex property names must be distinct and without NUL.
// The first two lines are the signature and the format, which CGAL checks.
inline void check_ply_header(const std::string& filename, std::uintmax_t file_size)
{
  std::ifstream in(filename, std::ios::binary);
  std::string line, element;
  std::vector<std::pair<std::string, std::string>> vertex_properties; // (name, type)
  bool has_faces = false, float_point = false;
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number)
  {
    std::istringstream tokens(line);
    std::string keyword;
    if(line_number <= 2 || !(tokens >> keyword))
      continue;
    if(keyword == "end_header")
      break;
    if(keyword == "element")
    {
      std::size_t items = 0; // read as CGAL reads it
      if(tokens >> element >> items)
        check_header_count(items, file_size, "items of element '" + element + "'");
      has_faces = has_faces || ((element == "face" || element == "faces") && items > 0);
    }
    else if(keyword == "property")
    {
      if(element.empty())
        throw Input_error("cannot parse the file as ply (a property before any element, line " +
                          std::to_string(line_number) + ")");
      std::string type, name;
      if((element == "vertex" || element == "vertices") && tokens >> type >> name)
      {
        if(type == "list" && !(tokens >> name >> name))
          continue; // `list SIZE_TYPE INDEX_TYPE NAME`; CGAL refuses the line
        bool repeated = name.find('\0') != std::string::npos;
        for(const auto& property : vertex_properties)
          repeated = repeated || property.first == name;
        if(repeated)
          throw Input_error("cannot parse the file as ply (vertex property '" + name.substr(0, name.find('\0')) +
                            "' given twice or with a NUL byte, line " + std::to_string(line_number) + ")");
        vertex_properties.emplace_back(name, type);
      }
    }
  }
  auto is_float = [](const std::string& type) { return type == "float" || type == "float32"; };
  for(const auto& property : vertex_properties)
    if(property.first == "x" || property.first == "y" || property.first == "z")
      float_point = float_point || is_float(property.second);
  for(const auto& property : vertex_properties)
  {
    const std::string& name = property.first;
    const bool is_point = (name == "x" || name == "y" || name == "z");
    if(!is_point && (has_faces || (name != "nx" && name != "ny" && name != "nz")))
      continue;
    const bool as_read = float_point && !has_faces ? is_float(property.second)
                                                   : is_float(property.second) || property.second == "double" ||
                                                       property.second == "float64";
    if(!as_read)
      throw Input_error("cannot parse the file as ply (vertex property '" + name + "' of type '" + property.second +
                        "': coordinates and normals must be float or double" +
                        (float_point && !has_faces ? ", all float when a coordinate is" : "") + ")");
  }
}

inline bool read_soup(const std::string& filename, const std::string& ext, std::uintmax_t file_size,
                      std::vector<Oriented_point_set::Point_3>& points,
                      std::vector<std::vector<std::size_t>>& polygons)
{
  if(ext == "off") return read_off_soup(filename, file_size, points, polygons);
  if(ext == "obj") return CGAL::IO::read_OBJ(filename, points, polygons);
  if(ext == "ply") return CGAL::IO::read_PLY(filename, points, polygons);
  if(ext == "stl") return CGAL::IO::read_STL(filename, points, polygons);
  return false;
}

inline void mesh_to_points(std::vector<Oriented_point_set::Point_3>& points,
                           std::vector<std::vector<std::size_t>>& polygons, Oriented_point_set& out)
{
  typedef Oriented_point_set::Point_3 Point_3;
  namespace PMP = CGAL::Polygon_mesh_processing;
  out.is_mesh = true;
  out.input_vertices = points.size();
  for(std::size_t v = 0; v < points.size(); ++v)
    check_coordinates(points[v], "vertex", v);

  // Vertices at one position become the first of them (SPEC §1), faces follow.
  std::map<std::array<double, 3>, std::size_t> first_at;
  std::vector<std::size_t> representative(points.size());
  std::vector<bool> referenced(points.size(), false);
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
    {
      if(v >= points.size())
        throw Input_error("a face refers to vertex " + std::to_string(v) + " of " + std::to_string(points.size()));
      referenced[v] = true;
    }
  std::vector<std::size_t> compact(points.size(), std::size_t(-1));
  std::vector<Point_3> distinct;
  std::size_t referenced_count = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    if(!referenced[v])
      continue;
    ++referenced_count;
    const auto inserted = first_at.emplace(std::array<double, 3>{{points[v].x(), points[v].y(), points[v].z()}}, v);
    representative[v] = inserted.first->second;
    if(inserted.second)
    {
      compact[v] = distinct.size();
      distinct.push_back(points[v]);
    }
  }
  out.dropped_vertices = points.size() - referenced_count;
  out.merged_duplicates = referenced_count - distinct.size();

  // Faces that collapse to fewer than three corners have no normal: left out.
  std::vector<std::vector<std::size_t>> faces;
  for(const auto& polygon : polygons)
  {
    std::vector<std::size_t> face;
    for(std::size_t v : polygon)
    {
      const std::size_t c = compact[representative[v]];
      if(std::find(face.begin(), face.end(), c) == face.end())
        face.push_back(c);
    }
    if(face.size() >= 3)
      faces.push_back(std::move(face));
  }
  if(faces.empty())
    throw Input_error("no face with three distinct corners");
  // Non-manifold or inconsistently oriented faces: CGAL orients them, splitting vertices where needed;
  // the split copies share a position and are merged again below.
  if(!PMP::is_polygon_soup_a_polygon_mesh(faces))
    PMP::orient_polygon_soup(distinct, faces);
  if(!PMP::is_polygon_soup_a_polygon_mesh(faces))
    throw Input_error("the faces do not form a polygon mesh, even after orientation");
  CGAL::Surface_mesh<Point_3> mesh;
  PMP::polygon_soup_to_polygon_mesh(distinct, faces, mesh);

  const auto mesh_points = internal::mesh_points(mesh, CGAL::parameters::default_values());
  // Vertices of `distinct` used by no kept face are isolated in `mesh`.
  out.dropped_vertices += mesh_points.summary.dropped_vertices();
  for(std::size_t i = 0; i < mesh_points.input.size(); ++i)
  {
    const auto& p = mesh_points.input.points[i];
    const auto& n = mesh_points.input.normals[i];
    out.points.emplace_back(p.x(), p.y(), p.z());
    out.normals.emplace_back(n[0], n[1], n[2]);
  }
}

inline void merge_duplicate_points(Oriented_point_set& out, bool has_normals)
{
  std::map<std::array<double, 3>, std::size_t> seen;
  std::size_t kept = 0;
  for(std::size_t i = 0; i < out.points.size(); ++i)
  {
    const auto& p = out.points[i];
    if(!seen.emplace(std::array<double, 3>{{p.x(), p.y(), p.z()}}, i).second)
      continue;
    out.points[kept] = out.points[i];
    if(has_normals)
      out.normals[kept] = out.normals[i];
    ++kept;
  }
  out.merged_duplicates = out.points.size() - kept;
  out.points.resize(kept);
  if(has_normals)
    out.normals.resize(kept);
}

// CGAL's jet fitting of degree 2 needs 6 points (a precondition of `Monge_via_jet_fitting`).
constexpr std::size_t FEWEST_POINTS_TO_ESTIMATE_NORMALS = 6;
// Jet fitting divides by the square of the extent of a point's neighbors; below this extent it
// underflows to 0, the least-squares matrix gets NaN, and Eigen 3.4's JacobiSVD, which leaves its
// rank undefined on non-finite input, reads out of bounds (a crash found by fuzzing).
constexpr double SMALLEST_NEIGHBORHOOD_EXTENT = 1e-150;

// Jet fitting and MST orientation (CGAL's Point_set_processing_3), in input order.
inline void estimate_normals(Oriented_point_set& out, unsigned int neighbors)
{
  {
    std::vector<Double_point> points;
    points.reserve(out.points.size());
    for(const auto& p : out.points)
      points.emplace_back(p.x(), p.y(), p.z());
    const K_neighbor_query query(points);
    std::vector<Neighbor> found;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      // the farthest of the `neighbors` nearest other points, as CGAL's query finds them
      query.query(std::uint32_t(i), neighbors, found);
      if(found.empty() ||
         !(found.back().squared_distance >= SMALLEST_NEIGHBORHOOD_EXTENT * SMALLEST_NEIGHBORHOOD_EXTENT))
        throw Input_error("point " + std::to_string(i) + " and its " + std::to_string(neighbors) +
                          " nearest points lie within 1e-150 of each other: too close to estimate normals");
    }
  }
  typedef std::tuple<Oriented_point_set::Point_3, Oriented_point_set::Vector_3, std::size_t> Item;
  std::vector<Item> items;
  for(std::size_t i = 0; i < out.points.size(); ++i)
    items.emplace_back(out.points[i], CGAL::NULL_VECTOR, i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Item>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Item>());
  CGAL::jet_estimate_normals<CGAL::Sequential_tag>(items, neighbors, np);
  const auto unoriented = CGAL::mst_orient_normals(items, neighbors, np);
  out.unoriented_normals = std::size_t(std::distance(unoriented, items.end()));
  std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return std::get<2>(x) < std::get<2>(y); });
  out.normals.clear();
  for(const Item& item : items)
    out.normals.push_back(std::get<1>(item));
  out.normals_estimated = true;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsIO
  \brief reads a mesh (OFF, PLY, OBJ, STL) or a point set (XYZ/PWN lines `x y z [nx ny nz]`,
  PLY with or without `nx ny nz`, OFF without faces) into distinct points with oriented unit normals,
  as SPEC §1 prescribes.

  Meshes: one point per vertex that has a face, its normal from
  `Polygon_mesh_processing::compute_vertex_normals()` (inconsistent orientations are repaired by
  `orient_polygon_soup()` first); vertices at one position merged, the first kept.
  Point sets: duplicates merged, the first kept; without normals, normals are estimated by jet
  fitting and oriented by a minimum spanning tree over `estimation_neighbors` neighbors; with
  `estimation_neighbors = 0` they are not estimated and `normals` comes back empty.

  \param filename the file; its extension (any case) selects the format: `.off`, `.obj`, `.ply`,
  `.stl`, `.xyz` or `.pwn`
  \param estimation_neighbors the number of neighbors of the normal estimation and orientation of
  point sets without normals, 0 or at least 6 (jet fitting of degree 2 needs 6 points; smaller
  values throw `std::invalid_argument`); 0 leaves them without normals
  \return the points, their normals, and counts of merged, dropped and unoriented points

  \throws Input_error with a one-line message on anything unusable: a missing, unreadable or empty
  file, an unknown extension, a syntax error, non-finite coordinates, zero or non-finite normals,
  no points.
*/
inline Oriented_point_set read_oriented_point_set(const std::string& filename, unsigned int estimation_neighbors = 18)
{
  typedef Oriented_point_set::Point_3 Point_3;
  typedef Oriented_point_set::Vector_3 Vector_3;
  if(estimation_neighbors != 0 && estimation_neighbors < internal::FEWEST_POINTS_TO_ESTIMATE_NORMALS)
    throw std::invalid_argument("read_oriented_point_set: estimation_neighbors must be 0 or at least " +
                                std::to_string(internal::FEWEST_POINTS_TO_ESTIMATE_NORMALS));
  Oriented_point_set out;
  const std::string ext = internal::lower_extension(filename);
  std::error_code ec;
  if(std::filesystem::is_directory(filename, ec))
    throw Input_error("is a folder, not a file");
  std::uintmax_t file_size = (std::numeric_limits<std::uintmax_t>::max)(); // unknown: no bound
  {
    std::ifstream probe(filename, std::ios::binary | std::ios::ate);
    if(!probe)
      throw Input_error("cannot open the file");
    const std::streampos end = probe.tellg();
    if(end == std::streampos(0))
      throw Input_error("the file is empty");
    if(end > std::streampos(0))
      file_size = std::uintmax_t(std::streamoff(end));
  }
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl" && ext != "xyz" && ext != "pwn")
    throw Input_error("unknown format '" + (ext.empty() ? std::string("(no extension)") : "." + ext) +
                      "': expected .off, .obj, .ply, .stl, .xyz or .pwn");

  bool has_normals = false;
  if(ext == "xyz" || ext == "pwn")
    internal::read_xyz(filename, out.points, out.normals, has_normals);
  else
  {
    std::vector<Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    std::string reason;
    bool soup_read;
    if(ext == "ply")
      internal::check_ply_header(filename, file_size);
    {
      internal::Captured_cerr captured;
      soup_read = internal::read_soup(filename, ext, file_size, points, polygons);
      reason = captured.first_line();
    }
    if(!reason.empty())
      reason = " (" + reason + ")";
    if(soup_read && !polygons.empty())
    {
      internal::mesh_to_points(points, polygons, out);
      return out;
    }
    if(!soup_read)
      throw Input_error("cannot parse the file as " + ext + (ext == "obj" ? ", or it has no faces" : "") + reason);
    if(ext == "obj" || ext == "stl")
      throw Input_error("no faces in the file");
    // OFF or PLY without faces: a point set, maybe with normals.
    CGAL::Point_set_3<Point_3, Vector_3> point_set;
    {
      internal::Captured_cerr captured;
      if(!CGAL::IO::read_point_set(filename, point_set))
      {
        const std::string why = captured.first_line();
        throw Input_error("cannot parse the file as " + ext + (why.empty() ? "" : " (" + why + ")"));
      }
    }
    has_normals = point_set.has_normal_map();
    for(auto it = point_set.begin(); it != point_set.end(); ++it)
    {
      out.points.push_back(point_set.point(*it));
      if(has_normals)
        out.normals.push_back(point_set.normal(*it));
    }
  }

  out.input_vertices = out.points.size();
  if(out.points.empty())
    throw Input_error("no points in the file");
  for(std::size_t i = 0; i < out.points.size(); ++i)
  {
    internal::check_coordinates(out.points[i], "point", i);
    if(has_normals)
    {
      const Vector_3& n = out.normals[i];
      const double squared_norm = n.squared_length();
      if(!std::isfinite(squared_norm))
        throw Input_error("point " + std::to_string(i) + " has a non-finite normal");
      if(!(squared_norm > 0.))
        throw Input_error("point " + std::to_string(i) + " has a zero normal");
      if(std::abs(squared_norm - 1.) > 1e-12)
        out.normals[i] = n / std::sqrt(squared_norm);
    }
  }
  internal::merge_duplicate_points(out, has_normals);
  if(!has_normals && estimation_neighbors == 0)
  {
    out.normals.clear();
    return out;
  }
  if(!has_normals)
  {
    if(out.points.size() < internal::FEWEST_POINTS_TO_ESTIMATE_NORMALS)
      throw Input_error("too few distinct points (" + std::to_string(out.points.size()) + ") to estimate normals");
    internal::estimate_normals(out, (std::min)(estimation_neighbors, unsigned(out.points.size() - 1)));
  }
  return out;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_IO_READ_ORIENTED_POINT_SET_H
