// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The JSON of the evaluation files: doubles round-trip bit for bit, non-finite ones are null, and
// the reader refuses what the tool could not have written, with the file and the key, before any
// unbounded work (size, depth, array sizes).

#include "evaluation_json.h"

#include "test_scratch.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using sigmoid_tool::Json;
using sigmoid_tool::Json_value;

std::uint64_t bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

fs::path scratch_file(const std::string& name, const std::string& content)
{
  const fs::path p = fs::path(scratch_folder("evaluation_files")) / name;
  std::ofstream(p, std::ios::binary) << content;
  return p;
}

std::string refusal(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch(const sigmoid_tool::Usage_error& e)
  {
    return e.what();
  }
  return "accepted";
}

} // namespace

TEST_CASE("evaluation files: doubles written through nlohmann::json read back bit for bit", "[evaluation][json]")
{
  std::vector<double> values = {0.,       -0.,     0.1,     1. / 3., CGAL_PI, 1e-300, 4.9406564584124654e-324,
                                1e308,    -2.5,    1e-06,   0.45102681179626236, std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::min(), 123456789012345678.};
  std::mt19937_64 rng(30);
  for(int i = 0; i < 10000; ++i)
  {
    std::uint64_t b = rng();
    double x;
    std::memcpy(&x, &b, sizeof x);
    if(std::isfinite(x))
      values.push_back(x);
  }
  Json j;
  j["values"] = values;
  std::ostringstream out;
  sigmoid_tool::write_json(out, j);
  const Json_value back = Json_value::parse(out.str());
  REQUIRE(back["values"].size() == values.size());
  for(std::size_t i = 0; i < values.size(); ++i)
  {
    INFO(i << ": " << values[i]);
    CHECK(bits(back["values"][i].get<double>()) == bits(values[i]));
    // the old writer's 17 digits name the same double
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", values[i]);
    CHECK(bits(std::strtod(text, nullptr)) == bits(back["values"][i].get<double>()));
  }
}

TEST_CASE("evaluation files: non-finite doubles are written as null and keys keep their order", "[evaluation][json]")
{
  Json j;
  j["z"] = std::numeric_limits<double>::quiet_NaN();
  j["a"] = std::numeric_limits<double>::infinity();
  j["m"] = -std::numeric_limits<double>::infinity();
  j["list"] = std::vector<double>{};
  std::ostringstream out;
  sigmoid_tool::write_json(out, j);
  CHECK(out.str() == "{\n  \"z\": null,\n  \"a\": null,\n  \"m\": null,\n  \"list\": []\n}\n");
}

TEST_CASE("evaluation files: the reader refuses deep nesting, large files and wrong types with the file and the key",
          "[evaluation][json][bad-input]")
{
  // 400 KB of '[': refused by the depth count before the recursive parser sees it
  const std::string brackets(400000, '[');
  CHECK(sigmoid_tool::json_depth(brackets, 16) == 17);
  const fs::path deep = scratch_file("deep.json", brackets);
  CHECK(refusal([&] { sigmoid_tool::read_json_file(deep.string(), sigmoid_tool::LARGEST_MODEL_FILE); })
          .find("nested deeper than 16") != std::string::npos);
  // brackets inside strings do not count
  CHECK(sigmoid_tool::json_depth("{\"a\": \"[[[[\\\"[[[[\"}", 16) == 1);
  const fs::path large = scratch_file("large.json", "[" + std::string(sigmoid_tool::LARGEST_MODEL_FILE, ' ') + "]");
  CHECK(refusal([&] { sigmoid_tool::read_json_file(large.string(), sigmoid_tool::LARGEST_MODEL_FILE); })
          .find("larger than the 1 MiB") != std::string::npos);
  const fs::path nan = scratch_file("nan.json", "{\"x\": NaN}");
  CHECK(refusal([&] { sigmoid_tool::read_json_file(nan.string(), sigmoid_tool::LARGEST_MODEL_FILE); })
          .find(nan.string() + ": not valid JSON") == 0);

  const Json_value j = Json_value::parse(R"({"k": "twenty", "n": -3, "f": 2.5, "big": 4000000000, "s": {"t": [1, 2]}})");
  const sigmoid_tool::Json_object o(j, "file.json");
  CHECK(refusal([&] { o.integer("k"); }) == "file.json: k is a string, expected an integer");
  CHECK(refusal([&] { o.integer("n"); }) == "file.json: n is -3, expected a count (an integer >= 0)");
  CHECK(refusal([&] { o.integer("f"); }) == "file.json: f is a number with a fraction or exponent, expected an integer");
  CHECK(refusal([&] { o.integer("big", 1, 1000000); }) == "file.json: big is 4000000000, expected 1 to 1000000");
  CHECK(refusal([&] { o.integer("missing"); }) == "file.json: missing is missing");
  CHECK(refusal([&] { o.object("s").integers("t", 3); }) == "file.json: s.t has 2 entries, expected 3");
  CHECK(refusal([&] { o.only({"k", "n"}); }).find("is not a key of this file") != std::string::npos);
}

TEST_CASE("evaluation files: the number of grid pairs is counted without listing them", "[evaluation][json]")
{
  CHECK(sigmoid_tool::number_of_pairs({0., 1., 2.}, {0., 1., 2.}) == 6);
  CHECK(sigmoid_tool::number_of_pairs({1.5}, {0., 1.}) == 0);
  const std::vector<double> many(200000, 0.);
  CHECK(sigmoid_tool::number_of_pairs(many, many) == std::uint64_t(200000) * 200000);
}
