// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// JSON for the evaluation files. Reading uses Boost.PropertyTree; writing is done here because
// PropertyTree's writer quotes every number, and the files must round-trip doubles (17 digits).

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_JSON_H
#define SIGMOID_NEIGHBORHOODS_TOOL_JSON_H

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace sigmoid_tool {

typedef boost::property_tree::ptree Json;

// A streaming writer with two-space indentation; non-finite numbers become null.
class Json_writer
{
public:
  explicit Json_writer(std::ostream& out) : m_out(out) {}

  Json_writer& begin_object(const char* key = nullptr) { return open(key, '{'); }
  Json_writer& end_object() { return close('}'); }
  Json_writer& begin_array(const char* key = nullptr) { return open(key, '['); }
  Json_writer& end_array() { return close(']'); }

  Json_writer& value(const char* key, const std::string& v)
  {
    prefix(key);
    write_string(v);
    return *this;
  }
  Json_writer& value(const char* key, const char* v) { return value(key, std::string(v)); }
  Json_writer& value(const char* key, double v)
  {
    prefix(key);
    if(std::isfinite(v))
    {
      char buffer[40];
      std::snprintf(buffer, sizeof(buffer), "%.17g", v);
      m_out << buffer;
    }
    else
      m_out << "null";
    return *this;
  }
  Json_writer& value(const char* key, std::size_t v)
  {
    prefix(key);
    m_out << v;
    return *this;
  }
  Json_writer& value(const char* key, unsigned int v) { return value(key, std::size_t(v)); }
  Json_writer& value(const char* key, bool v)
  {
    prefix(key);
    m_out << (v ? "true" : "false");
    return *this;
  }
  template <typename T>
  Json_writer& array(const char* key, const std::vector<T>& values)
  {
    begin_array(key);
    for(const T& v : values)
      value(nullptr, v);
    return end_array();
  }
  void finish() { m_out << '\n'; }

private:
  Json_writer& open(const char* key, char bracket)
  {
    prefix(key);
    m_out << bracket;
    m_first.push_back(true);
    return *this;
  }
  Json_writer& close(char bracket)
  {
    const bool empty = m_first.back();
    m_first.pop_back();
    if(!empty)
      newline();
    m_out << bracket;
    return *this;
  }
  void newline()
  {
    m_out << '\n';
    for(std::size_t i = 0; i < m_first.size(); ++i)
      m_out << "  ";
  }
  void prefix(const char* key)
  {
    if(!m_first.empty())
    {
      if(!m_first.back())
        m_out << ',';
      m_first.back() = false;
      newline();
    }
    if(key)
    {
      write_string(key);
      m_out << ": ";
    }
  }
  void write_string(const std::string& s)
  {
    m_out << '"';
    for(char c : s)
    {
      switch(c)
      {
        case '"': m_out << "\\\""; break;
        case '\\': m_out << "\\\\"; break;
        case '\n': m_out << "\\n"; break;
        case '\t': m_out << "\\t"; break;
        case '\r': m_out << "\\r"; break;
        default:
          if(static_cast<unsigned char>(c) < 0x20)
          {
            char buffer[8];
            std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
            m_out << buffer;
          }
          else
            m_out << c;
      }
    }
    m_out << '"';
  }

  std::ostream& m_out;
  std::vector<bool> m_first;
};

inline Json read_json(const std::string& path)
{
  Json tree;
  boost::property_tree::read_json(path, tree);
  return tree;
}

// A number written by Json_writer; null reads as `if_null`.
inline double json_double(const Json& tree, const std::string& key, double if_null)
{
  const std::string text = tree.get<std::string>(key);
  return text == "null" || text.empty() ? if_null : std::stod(text);
}

inline std::size_t json_size(const Json& tree, const std::string& key) { return tree.get<std::size_t>(key); }

template <typename T>
std::vector<T> json_array(const Json& tree, const std::string& key)
{
  std::vector<T> result;
  for(const auto& child : tree.get_child(key))
    result.push_back(child.second.get_value<T>());
  return result;
}

inline std::vector<double> json_double_array(const Json& tree, const std::string& key)
{
  std::vector<double> result;
  for(const auto& child : tree.get_child(key))
    result.push_back(std::stod(child.second.get_value<std::string>()));
  return result;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_JSON_H
