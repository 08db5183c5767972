// system_torque_limiter: the torque limiter at the PDU output (torque_limiter.h).
#include "torque_limiter.h"

namespace highlift::model::components {
namespace {
class SystemTorqueLimiterModel final : public TorqueLimiterModel {
 public:
  SystemTorqueLimiterModel() : TorqueLimiterModel("system_torque_limiter", {.lumps_inertia = true, .wing_limiter = true}) {}
};
}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(SystemTorqueLimiter, SystemTorqueLimiterModel)
