// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors
//
// A libFuzzer target over the LAS and LAZ readers alone: the input is a whole file, read from memory
// by read_las_header() and for_each_las_record_block() on one and on two threads. Expected outcomes:
// the records, or an Input_error (the command's exit code 2). Findings: a crash, a sanitizer
// report, a hang, an allocation over -malloc_limit_mb, any other exception, and records or an error
// message that differ between one and two threads. Seeds: the LAZ files of ../shared/data/laz
// (`make fuzz-laz`).
//
// Built with SIGMOID_NEIGHBORHOODS_LIBFUZZER (clang, -fsanitize=fuzzer) this is the fuzzer;
// without it, a `main` replays the files given on the command line.

#include <Sigmoid_neighborhoods_readers/internal/read_las.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

namespace SN = CGAL::Sigmoid_neighborhoods;

// The records of `bytes` as a LAS or LAZ file, on `threads`, or the message of its Input_error
// (the records delivered before a damaged chunk are dropped, as a command drops them).
std::string records(const std::string& bytes, unsigned int threads)
{
  std::string out;
  std::istringstream in(bytes);
  try
  {
    const Lidar_io::Las_header h = Lidar_io::internal::read_las_header(in, bytes.size());
    Lidar_io::internal::for_each_las_record_block(in, h, threads, [&](std::size_t, const unsigned char* r, std::size_t n) {
      out.append(reinterpret_cast<const char*>(r), n * h.record_length);
    });
  }
  catch(const SN::Input_error& e)
  {
    return std::string("error: ") + e.what();
  }
  return out;
}

int run_one(const std::uint8_t* data, std::size_t size)
{
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  if(records(bytes, 1) != records(bytes, 2))
  {
    std::fprintf(stderr, "fuzz_laz: one and two threads differ\n");
    std::abort();
  }
  return 0;
}

} // namespace

#ifdef SIGMOID_NEIGHBORHOODS_LIBFUZZER
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { return run_one(data, size); }
#else
int main(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i)
  {
    std::ifstream in(argv[i], std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    const std::string bytes = s.str();
    run_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << "replayed " << (argc - 1) << " inputs\n";
  return 0;
}
#endif
