#pragma once
/// \file
/// Umbrella header: the whole library.

#include "newtop/core/types.hpp"
#include "newtop/integrate/concepts.hpp"
#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/model/body.hpp"
#include "newtop/model/field.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/model.hpp"
