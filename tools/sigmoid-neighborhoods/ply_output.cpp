// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ply_output.h, compiled once for the tool.

#include "ply_output.h"

namespace sigmoid_tool {

Ply_colors read_ply_colors(const Arguments& args)
{
  const std::string text = args.get("--color", "error");
  if(text == "error")
    return Ply_colors::ERROR;
  if(text == "label")
    return Ply_colors::LABEL;
  if(text == "none")
    return Ply_colors::NONE;
  throw Usage_error("--color must be error, label or none, got '" + text + "'");
}

Rgb viridis(double t)
{
  const double at = std::clamp(t, 0., 1.) * double(VIRIDIS_SAMPLES.size() - 1);
  const std::size_t i = std::min<std::size_t>(std::size_t(at), VIRIDIS_SAMPLES.size() - 2);
  const double f = at - double(i);
  Rgb rgb;
  for(std::size_t c = 0; c < 3; ++c)
  {
    const double v = (1. - f) * VIRIDIS_SAMPLES[i][c] + f * VIRIDIS_SAMPLES[i + 1][c];
    rgb[c] = std::uint8_t(std::lround(255. * v));
  }
  return rgb;
}

Rgb error_color(double error)
{
  return std::isfinite(error) ? viridis(error / std::log(3.)) : FAILURE_GRAY;
}

Rgb label_color(CGAL::Sigmoid_neighborhoods::Dimensionality label)
{
  typedef CGAL::Sigmoid_neighborhoods::Dimensionality D;
  switch(label)
  {
  case D::LINEAR: return {213, 94, 0};      // vermillion
  case D::PLANAR: return {0, 114, 178};     // blue
  case D::SCATTERED: return {240, 228, 66}; // yellow
  default: return FAILURE_GRAY;             // degenerate
  }
}

void write_binary_ply(std::ostream& out, const Ply_point_set& ps)
{
  CGAL::IO::set_binary_mode(out);
  if(!CGAL::IO::write_PLY(out, ps))
    throw Usage_error("cannot write the PLY file");
}
} // namespace sigmoid_tool
