// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The classes of a classification and the file codes (LAS classification, PLY label) each one
// gathers: `ground=2,vegetation=3+4+5,building=6`. Codes named nowhere are ignored.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_LABEL_MAPPING_H
#define SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_LABEL_MAPPING_H

#include "../command_line.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace sigmoid_tool {

struct Label_mapping
{
  std::vector<std::string> names;       // class index -> name
  std::vector<std::vector<int>> codes;  // class index -> its file codes
  std::map<int, int> class_of_code;     // file code -> class index

  // -1 for a code of no class: the point takes no part in training or evaluation
  int class_of(int code) const
  {
    const auto it = class_of_code.find(code);
    return it == class_of_code.end() ? -1 : it->second;
  }

  std::string text() const
  {
    std::string result;
    for(std::size_t c = 0; c < names.size(); ++c)
    {
      result += (c ? "," : "") + names[c] + "=";
      for(std::size_t j = 0; j < codes[c].size(); ++j)
        result += (j ? "+" : "") + std::to_string(codes[c][j]);
    }
    return result;
  }
};

// The classes of the IGN LiDAR HD and ASPRS codes that the experiment uses.
const char* const DEFAULT_LABELS = "ground=2,low_vegetation=3+4,high_vegetation=5,building=6";

inline Label_mapping parse_label_mapping(const std::string& text)
{
  Label_mapping m;
  for(const std::string& item : split(text, ','))
  {
    const std::size_t equals = item.find('=');
    if(equals == std::string::npos || equals == 0 || equals + 1 == item.size())
      throw Usage_error("--labels: expected NAME=CODE[+CODE...], got '" + item + "'");
    const std::string name = item.substr(0, equals);
    for(char c : name)
      if(!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
        throw Usage_error("--labels: a class name has letters, digits, '_' and '-' only, got '" + name + "'");
    for(const std::string& other : m.names)
      if(other == name)
        throw Usage_error("--labels: class '" + name + "' named twice");
    const int index = int(m.names.size());
    m.names.push_back(name);
    m.codes.emplace_back();
    for(const std::string& code_text : split(item.substr(equals + 1), '+'))
    {
      char* end = nullptr;
      const long code = std::strtol(code_text.c_str(), &end, 10);
      if(code_text.empty() || *end != '\0' || code < 0 || code > 65535)
        throw Usage_error("--labels: a code is an integer in [0, 65535], got '" + code_text + "' in '" + item + "'");
      if(!m.class_of_code.emplace(int(code), index).second)
        throw Usage_error("--labels: code " + code_text + " is in two classes");
      m.codes.back().push_back(int(code));
    }
  }
  if(m.names.size() < 2)
    throw Usage_error("--labels: a classification needs at least two classes");
  return m;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_CLASSIFICATION_LABEL_MAPPING_H
