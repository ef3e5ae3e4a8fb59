#pragma once
/// \file
/// JSON output (nlohmann-json, keys in insertion order) and the fragments every command shares.

#include <nlohmann/json.hpp>

#include "newtop/core/types.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop::io {

using Json = nlohmann::ordered_json;

/// {"energy": …, "area": …, "geometric": …[, "brun": …][, "lagrange": …]}
Json to_json(const IntegralValues& v);
Json to_json(const Vec3& v);

}  // namespace newtop::io
