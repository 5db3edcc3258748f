// SPDX-License-Identifier: MIT
// A driver file that breaks the layers (never compiled): the layer check must reject both includes.
#include "reference/common/engine.hpp"
#include "reference/yade/yade_engine.hpp"
#  include <reference/registry.hpp>
