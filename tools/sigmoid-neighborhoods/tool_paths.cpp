// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "tool_paths.h"

#ifndef SIGMOID_NEIGHBORHOODS_SCRIPT_DIR
#define SIGMOID_NEIGHBORHOODS_SCRIPT_DIR "."
#endif
#ifndef SIGMOID_NEIGHBORHOODS_APPLICATION_DATA
#define SIGMOID_NEIGHBORHOODS_APPLICATION_DATA ""
#endif
#ifndef SIGMOID_NEIGHBORHOODS_DEFAULT_FANDISK
#define SIGMOID_NEIGHBORHOODS_DEFAULT_FANDISK ""
#endif
#ifndef SIGMOID_NEIGHBORHOODS_SHARED_DATA
#define SIGMOID_NEIGHBORHOODS_SHARED_DATA ""
#endif

namespace sigmoid_tool {
namespace tool_paths {

const char* script_dir() { return SIGMOID_NEIGHBORHOODS_SCRIPT_DIR; }
const char* application_data() { return SIGMOID_NEIGHBORHOODS_APPLICATION_DATA; }
const char* default_fandisk() { return SIGMOID_NEIGHBORHOODS_DEFAULT_FANDISK; }
const char* shared_data() { return SIGMOID_NEIGHBORHOODS_SHARED_DATA; }

} // namespace tool_paths
} // namespace sigmoid_tool
