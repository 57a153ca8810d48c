// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef LIDAR_IO_LOWER_CASE_EXTENSION_H
#define LIDAR_IO_LOWER_CASE_EXTENSION_H

#include <cctype>
#include <string>

namespace Lidar_io {

/*!
  \ingroup PkgLidarIo
  returns the extension of `filename` in lower case, without the dot (`"Model.PLY"` gives `"ply"`),
  or an empty string when its last path component has no dot. The readers select the format with it.
*/
inline std::string lower_case_extension(const std::string& filename)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string extension = filename.substr(dot + 1);
  for(char& c : extension)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

} // namespace Lidar_io

#endif // LIDAR_IO_LOWER_CASE_EXTENSION_H
