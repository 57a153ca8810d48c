// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// json.h, compiled once for the tool.

#include "json.h"

namespace sigmoid_tool {

void write_json(std::ostream& out, const Json& j)
{
  out << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

std::string as_written(const std::string& text)
{
  return Json_value::parse(Json(text).dump(-1, ' ', false, Json::error_handler_t::replace)).get<std::string>();
}

int json_depth(const std::string& text, int limit)
{
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for(char c : text)
  {
    if(in_string)
    {
      if(escaped)
        escaped = false;
      else if(c == '\\')
        escaped = true;
      else if(c == '"')
        in_string = false;
      continue;
    }
    if(c == '"')
      in_string = true;
    else if(c == '[' || c == '{')
    {
      deepest = (std::max)(deepest, ++depth);
      if(deepest > limit)
        break;
    }
    else if(c == ']' || c == '}')
      --depth;
  }
  return deepest;
}

Usage_error json_error(const std::string& file, const std::string& what)
{ return Usage_error(file + ": " + what); }

Json_value read_json_file(const std::string& path, std::uintmax_t largest)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!fs::is_regular_file(path, ec))
    throw json_error(path, "not a file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if(ec)
    throw json_error(path, "cannot read the file (" + ec.message() + ")");
  if(bytes > largest)
    throw json_error(path, "a file of " + std::to_string(bytes) + " bytes, larger than the " +
                             std::to_string(largest >> 20) + " MiB of an evaluation file");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw json_error(path, "cannot open the file");
  std::string text;
  text.reserve(std::size_t(bytes));
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if(text.size() > largest) // grown since its size was read
    throw json_error(path, "larger than the " + std::to_string(largest >> 20) + " MiB of an evaluation file");
  return parse_json_text(text, path);
}

Json_value parse_json_text(const std::string& text, const std::string& file)
{
  if(json_depth(text, DEEPEST_JSON) > DEEPEST_JSON)
    throw json_error(file, "arrays or objects nested deeper than " + std::to_string(DEEPEST_JSON) +
                             ": not a file of the tool");
  try
  {
    return Json_value::parse(text);
  }
  catch(const Json_value::exception& e)
  {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ...": the part after the tag
    std::string what = e.what();
    const std::size_t tag = what.find("] ");
    if(tag != std::string::npos)
      what = what.substr(tag + 2);
    throw json_error(file, "not valid JSON: " + what);
  }
}

} // namespace sigmoid_tool
