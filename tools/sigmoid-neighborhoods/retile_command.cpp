// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `catalog retile` in a translation unit of its own: the LAZ decoder and encoder it instantiates
// compile beside `catalog list` and `merge`, not after them.

#include "commands.h"

#include "retile_command.h"

namespace sigmoid_tool {

int run_catalog_retile(int argc, char** argv, const char* usage) { return run_retile(argc, argv, usage); }

} // namespace sigmoid_tool
