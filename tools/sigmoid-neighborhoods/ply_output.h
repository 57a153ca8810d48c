// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The PLY point clouds of the tool, as the viewers read them: per-point values as `scalar_<name>`
// properties (CloudCompare's own naming: it loads those as scalar fields and drops other names), and
// for MeshLab and the other viewers a per-vertex `quality` (E_dim) and colors `red green blue`
// (`--color error|label|none`). CGAL's `Point_set_3` reads every property back by that name.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_PLY_OUTPUT_H
#define SIGMOID_NEIGHBORHOODS_TOOL_PLY_OUTPUT_H

#include "command_line.h"

#include <CGAL/Sigmoid_neighborhoods/dimensionality_features.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>

namespace sigmoid_tool {

typedef CGAL::Point_set_3<CGAL::Sigmoid_neighborhoods::Oriented_point_set::Point_3,
                          CGAL::Sigmoid_neighborhoods::Oriented_point_set::Vector_3>
  Ply_point_set;

// CloudCompare 2.11 writes and reads per-point values as `scalar_<name>`, as the package's
// Point_set_3 overloads name their properties.
const std::string PLY_SCALAR_PREFIX = "scalar_";

// The property `scalar_<name>` of type T, 0 by default.
template <typename T>
typename Ply_point_set::template Property_map<T> add_ply_scalar(Ply_point_set& ps, const std::string& name)
{
  return ps.template add_property_map<T>(PLY_SCALAR_PREFIX + name, T(0)).first;
}

// What the vertex colors show.
enum class Ply_colors
{
  ERROR, // E_dim over [0, ln 3] through viridis, gray for a failure
  LABEL, // one color per dimensionality label
  NONE   // no color properties
};

inline const char* COLOR_USAGE =
  "  --color error|label|none: the PLY's vertex colors (default error): E_dim over [0, ln 3] through viridis\n"
  "      (failures gray), or by label (linear vermillion, planar blue, scattered yellow, degenerate gray)\n";

Ply_colors read_ply_colors(const Arguments& args);

typedef std::array<std::uint8_t, 3> Rgb;

// A point without a result (infinite E_dim, the degenerate label): in no palette below.
constexpr Rgb FAILURE_GRAY = {128, 128, 128};

// Viridis (matplotlib's perceptually uniform map) at every 5th of its 256 entries, 0 to 255:
// linear interpolation between them stays within 1 of 255 of the full table.
constexpr std::array<std::array<float, 3>, 52> VIRIDIS_SAMPLES = {{
  {0.267004f, 0.004874f, 0.329415f}, {0.273809f, 0.031497f, 0.358853f}, {0.278791f, 0.062145f, 0.386592f},
  {0.281924f, 0.089666f, 0.412415f}, {0.283197f, 0.115680f, 0.436115f}, {0.282623f, 0.140926f, 0.457517f},
  {0.280255f, 0.165693f, 0.476498f}, {0.276194f, 0.190074f, 0.493001f}, {0.270595f, 0.214069f, 0.507052f},
  {0.263663f, 0.237631f, 0.518762f}, {0.255645f, 0.260703f, 0.528312f}, {0.246811f, 0.283237f, 0.535941f},
  {0.237441f, 0.305202f, 0.541921f}, {0.227802f, 0.326594f, 0.546532f}, {0.218130f, 0.347432f, 0.550038f},
  {0.208623f, 0.367752f, 0.552675f}, {0.199430f, 0.387607f, 0.554642f}, {0.190631f, 0.407061f, 0.556089f},
  {0.182256f, 0.426184f, 0.557120f}, {0.174274f, 0.445044f, 0.557792f}, {0.166617f, 0.463708f, 0.558119f},
  {0.159194f, 0.482237f, 0.558073f}, {0.151918f, 0.500685f, 0.557587f}, {0.144759f, 0.519093f, 0.556572f},
  {0.137770f, 0.537492f, 0.554906f}, {0.131172f, 0.555899f, 0.552459f}, {0.125394f, 0.574318f, 0.549086f},
  {0.121148f, 0.592739f, 0.544641f}, {0.119423f, 0.611141f, 0.538982f}, {0.121380f, 0.629492f, 0.531973f},
  {0.128087f, 0.647749f, 0.523491f}, {0.140210f, 0.665859f, 0.513427f}, {0.157851f, 0.683765f, 0.501686f},
  {0.180653f, 0.701402f, 0.488189f}, {0.208030f, 0.718701f, 0.472873f}, {0.239374f, 0.735588f, 0.455688f},
  {0.274149f, 0.751988f, 0.436601f}, {0.311925f, 0.767822f, 0.415586f}, {0.352360f, 0.783011f, 0.392636f},
  {0.395174f, 0.797475f, 0.367757f}, {0.440137f, 0.811138f, 0.340967f}, {0.487026f, 0.823929f, 0.312321f},
  {0.535621f, 0.835785f, 0.281908f}, {0.585678f, 0.846661f, 0.249897f}, {0.636902f, 0.856542f, 0.216620f},
  {0.688944f, 0.865448f, 0.182725f}, {0.741388f, 0.873449f, 0.149561f}, {0.793760f, 0.880678f, 0.120005f},
  {0.845561f, 0.887322f, 0.099702f}, {0.896320f, 0.893616f, 0.096335f}, {0.945636f, 0.899815f, 0.112838f},
  {0.993248f, 0.906157f, 0.143936f},
}};

// Viridis at t in [0, 1] (clamped).
Rgb viridis(double t);

// E_dim over its range [0, ln 3]; gray for a failure (infinite or NaN error).
Rgb error_color(double error);

// The Okabe-Ito colors, told apart with every common color vision deficiency.
Rgb label_color(CGAL::Sigmoid_neighborhoods::Dimensionality label);

// The per-vertex `quality` (float: MeshLab's type) and, unless `colors` is NONE, `red green blue`.
class Ply_viewer_properties
{
public:
  Ply_viewer_properties(Ply_point_set& ps, Ply_colors colors) : m_colors(colors)
  {
    m_quality = ps.add_property_map<float>("quality", 0.f).first;
    if(m_colors != Ply_colors::NONE)
    {
      m_red = ps.add_property_map<std::uint8_t>("red", 0).first;
      m_green = ps.add_property_map<std::uint8_t>("green", 0).first;
      m_blue = ps.add_property_map<std::uint8_t>("blue", 0).first;
    }
  }

  void set(Ply_point_set::Index i, double error, CGAL::Sigmoid_neighborhoods::Dimensionality label)
  {
    m_quality[i] = float(error);
    if(m_colors == Ply_colors::NONE)
      return;
    const Rgb rgb = m_colors == Ply_colors::ERROR ? error_color(error) : label_color(label);
    m_red[i] = rgb[0];
    m_green[i] = rgb[1];
    m_blue[i] = rgb[2];
  }

private:
  Ply_colors m_colors;
  Ply_point_set::Property_map<float> m_quality;
  Ply_point_set::Property_map<std::uint8_t> m_red, m_green, m_blue;
};

// A binary little-endian PLY with every property of `ps` in the order it was added.
void write_binary_ply(std::ostream& out, const Ply_point_set& ps);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_PLY_OUTPUT_H
