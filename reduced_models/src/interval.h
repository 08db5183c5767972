// The outward-rounded interval of the reduced-model laws is the model layer's
// (highlift/model/interval.h), shared with the component laws; these names keep the reduced
// models' code unchanged.
#pragma once

#include "highlift/model/interval.h"

namespace highlift::reduced_models::detail {

using model::abs;
using model::BySign;
using model::Down;
using model::exp;
using model::HasNonNegativePart;
using model::HasNonPositivePart;
using model::Hull;
using model::Interval;
using model::Lower;
using model::Outward;
using model::sqrt;
using model::tanh;
using model::Up;
using model::Upper;

}  // namespace highlift::reduced_models::detail
