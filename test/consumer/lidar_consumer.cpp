// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A program of another project on the installed lidar IO library alone: writes three points to a
// LAS file, reads them back.

#include <Lidar_io/Las_writer.h>
#include <Lidar_io/read_las_records.h>
#include <Lidar_io/read_tile_catalog.h>

#include <fstream>
#include <iostream>
#include <vector>

int main()
{
  const Lidar_io::Las_output_layout layout = Lidar_io::las_output_layout_for({{0., 0., 0.}}, {{2., 2., 2.}}, {}, 6, 0);
  std::vector<unsigned char> records(3 * layout.record_length, 0);
  for(int i = 0; i < 3; ++i)
    Lidar_io::store_las_coordinates(records.data() + i * layout.record_length, layout, {{1. * i, 1. * i, 1. * i}});
  {
    std::ofstream out("three.las", std::ios::binary | std::ios::trunc);
    Lidar_io::Las_writer writer(out, layout);
    writer.write(records.data(), 3);
    writer.close();
  }
  std::size_t read = 0;
  Lidar_io::read_las_records("three.las", [&](std::size_t, const unsigned char*, std::size_t n) { read += n; });
  std::cout << read << " records\n";
  return Lidar_io::read_tile_catalog(".").tiles.size() == 1 ? 0 : 1;
}
