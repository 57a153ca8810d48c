// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// JSON for the evaluation files, through nlohmann::json. Writing keeps the keys in the order they
// are set and writes doubles as the shortest text that reads back to the same double (non-finite
// ones as null). Reading treats a file as untrusted input, like a point file: a size cap before
// parsing, a depth cap before the parser (recursive) sees the text, and checked accessors that
// name the file and the key of anything wrong, as a Usage_error (exit code 2).

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_JSON_H
#define SIGMOID_NEIGHBORHOODS_TOOL_JSON_H

#include "command_line.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace sigmoid_tool {

// What the tool writes: keys in insertion order, so that a file reads as the code writes it.
typedef nlohmann::ordered_json Json;

// What the tool reads.
typedef nlohmann::json Json_value;

// The largest evaluation file read: a model file of the tool holds some 20 KB with the default
// grids, 1 MiB leaves room for grids of some 200 angles; summary.json holds about 110 bytes per
// model, 16 MiB a repository of about 150,000 models (and it is refused first when larger than twice
// the summary its model files give); failures.json about 100 bytes per failed model, 4 MiB some
// 40,000 of them. Parsed, a file takes up to some 26 times its size.
constexpr std::uintmax_t LARGEST_MODEL_FILE = std::uintmax_t(1) << 20;
constexpr std::uintmax_t LARGEST_SUMMARY_FILE = std::uintmax_t(1) << 24;
constexpr std::uintmax_t LARGEST_FAILURES_FILE = std::uintmax_t(1) << 22;

// The deepest nesting of arrays and objects read: the tool's files nest 4 deep.
constexpr int DEEPEST_JSON = 16;

// A JSON file as written by the tool, with a final newline. Strings that are not UTF-8 (a file
// name in another encoding) get U+FFFD for their bad bytes, so that the file stays JSON.
void write_json(std::ostream& out, const Json& j);

// `text` as a JSON string of the tool's files reads back (see write_json).
std::string as_written(const std::string& text);

// The depth of the deepest array or object of `text`, counted without parsing; stops counting
// beyond `limit`.
int json_depth(const std::string& text, int limit);

// An error in an evaluation file: `FILE: what is wrong`, exit code 2.
Usage_error json_error(const std::string& file, const std::string& what);

// Reads and parses `path`, refused when larger than `largest` bytes or nested deeper than DEEPEST_JSON.
Json_value read_json_file(const std::string& path, std::uintmax_t largest);

// Parses `text` read from `file` (a line of a file of the tool), refused when nested deeper than
// DEEPEST_JSON or not JSON, with a message naming `file`.
Json_value parse_json_text(const std::string& text, const std::string& file);

// The largest count (points, models, histogram entries) read: 2^40, far beyond any evaluation,
// so that sums over a million models still fit in 64 bits.
constexpr std::uint64_t LARGEST_COUNT = std::uint64_t(1) << 40;

// A checked view of a JSON object of an evaluation file: every accessor names the file and the
// key of a missing value, a value of the wrong type or out of range.
class Json_object
{
public:
  Json_object(const Json_value& j, const std::string& file, const std::string& where = std::string())
    : m_j(j), m_file(file), m_where(where)
  {
    if(!m_j.is_object())
      fail(m_where.empty() ? std::string("the file") : m_where, "is " + type_name(m_j) + ", expected an object");
  }

  const std::string& file() const { return m_file; }
  bool has(const char* key) const { return m_j.contains(key); }

  // Refuses keys other than `allowed`: a misspelt key is an edited file.
  void only(std::initializer_list<const char*> allowed) const
  {
    for(auto it = m_j.begin(); it != m_j.end(); ++it)
      if(std::find_if(allowed.begin(), allowed.end(), [&](const char* a) { return it.key() == a; }) == allowed.end())
        fail(name(it.key()), "is not a key of this file");
  }

  Json_object object(const char* key) const { return Json_object(at(key), m_file, name(key)); }

  const Json_value& array(const char* key, std::size_t largest = std::numeric_limits<std::size_t>::max()) const
  {
    const Json_value& v = at(key);
    if(!v.is_array())
      fail(name(key), "is " + type_name(v) + ", expected an array");
    if(v.size() > largest)
      fail(name(key), "has " + std::to_string(v.size()) + " entries, more than " + std::to_string(largest));
    return v;
  }

  // A non-negative integer in [lowest, largest].
  std::uint64_t integer(const char* key, std::uint64_t lowest = 0, std::uint64_t largest = LARGEST_COUNT) const
  {
    return integer_value(at(key), name(key), lowest, largest);
  }
  std::uint64_t integer_or(const char* key, std::uint64_t fallback, std::uint64_t lowest = 0,
                           std::uint64_t largest = LARGEST_COUNT) const
  {
    return has(key) ? integer(key, lowest, largest) : fallback;
  }

  // A finite number, or null (the writer's non-finite numbers) read as `if_null`.
  double number(const char* key, double if_null) const { return number_value(at(key), name(key), if_null); }

  std::string string(const char* key, std::size_t longest = 4096) const
  {
    const Json_value& v = at(key);
    if(!v.is_string())
      fail(name(key), "is " + type_name(v) + ", expected a string");
    const std::string& s = v.get_ref<const std::string&>();
    if(s.size() > longest)
      fail(name(key), "is a string of " + std::to_string(s.size()) + " bytes, longer than " + std::to_string(longest));
    return s;
  }

  // One of `values`.
  std::string choice(const char* key, std::initializer_list<const char*> values) const
  {
    const std::string s = string(key, 64);
    std::string list;
    for(const char* v : values)
    {
      if(s == v)
        return s;
      list += (list.empty() ? "" : ", ") + std::string(v);
    }
    fail(name(key), "is '" + s + "', expected one of " + list);
    return s;
  }

  bool boolean(const char* key) const
  {
    const Json_value& v = at(key);
    if(!v.is_boolean())
      fail(name(key), "is " + type_name(v) + ", expected true or false");
    return v.get<bool>();
  }

  std::vector<std::uint64_t> integers(const char* key, std::size_t size, std::uint64_t largest = LARGEST_COUNT) const
  {
    const Json_value& v = array(key);
    if(v.size() != size)
      fail(name(key), "has " + std::to_string(v.size()) + " entries, expected " + std::to_string(size));
    std::vector<std::uint64_t> result;
    result.reserve(v.size());
    for(std::size_t i = 0; i < v.size(); ++i)
      result.push_back(integer_value(v[i], name(key) + "[" + std::to_string(i) + "]", 0, largest));
    return result;
  }

  // Finite numbers (no null).
  std::vector<double> numbers(const char* key, std::size_t largest_size) const
  {
    const Json_value& v = array(key, largest_size);
    std::vector<double> result;
    result.reserve(v.size());
    for(std::size_t i = 0; i < v.size(); ++i)
    {
      const std::string where = name(key) + "[" + std::to_string(i) + "]";
      if(v[i].is_null())
        fail(where, "is null, expected a number");
      result.push_back(number_value(v[i], where, 0.));
    }
    return result;
  }

  // `FILE: KEY what`.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const
  {
    // a forged key can be as long as the file: the message stays one short line
    const std::string shown = key.size() > 200 ? key.substr(0, 200) + "..." : key;
    throw json_error(m_file, shown + " " + what);
  }

  std::string name(const std::string& key) const { return m_where.empty() ? key : m_where + "." + key; }

  static std::string type_name(const Json_value& v)
  {
    return v.is_null() ? "null" : v.is_boolean() ? "a boolean" : v.is_number_float() ? "a number with a fraction or exponent"
           : v.is_number() ? "an integer" : v.is_string() ? "a string" : v.is_array() ? "an array" : "an object";
  }

private:
  const Json_value& at(const char* key) const
  {
    const auto it = m_j.find(key);
    if(it == m_j.end())
      fail(name(key), "is missing");
    return *it;
  }

  std::uint64_t integer_value(const Json_value& v, const std::string& where, std::uint64_t lowest,
                              std::uint64_t largest) const
  {
    if(v.is_number_integer() && !v.is_number_unsigned())
      fail(where, "is " + std::to_string(v.get<std::int64_t>()) + ", expected a count (an integer >= 0)");
    if(!v.is_number_unsigned())
      fail(where, "is " + type_name(v) + ", expected an integer");
    const std::uint64_t x = v.get<std::uint64_t>();
    if(x < lowest || x > largest)
      fail(where, "is " + std::to_string(x) + ", expected " + std::to_string(lowest) + " to " + std::to_string(largest));
    return x;
  }

  double number_value(const Json_value& v, const std::string& where, double if_null) const
  {
    if(v.is_null())
      return if_null;
    if(!v.is_number())
      fail(where, "is " + type_name(v) + ", expected a number");
    const double x = v.get<double>();
    if(!std::isfinite(x))
      fail(where, "is not a finite number");
    return x;
  }

  const Json_value& m_j;
  std::string m_file, m_where;
};

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_JSON_H
