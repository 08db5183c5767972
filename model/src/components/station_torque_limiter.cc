// station_torque_limiter: the torque limiter in front of a station's actuator (torque_limiter.h).
#include "torque_limiter.h"

namespace highlift::model::components {
namespace {
class StationTorqueLimiterModel final : public TorqueLimiterModel {
 public:
  StationTorqueLimiterModel() : TorqueLimiterModel("station_torque_limiter", {.lumps_inertia = true, .station_limiter = true}) {}
};
}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(StationTorqueLimiter, StationTorqueLimiterModel)
