// SUNDIALS version differences in one place. Debian ships SUNDIALS 6.4: sunrealtype exists,
// every constructor takes a SUNContext. Older releases (5.x) used realtype and no context.
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_types.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <string>

#if SUNDIALS_VERSION_MAJOR < 6
#error "highlift needs SUNDIALS >= 6 (SUNContext, sunrealtype)"
#endif

namespace highlift::sim::detail {

static_assert(sizeof(sunrealtype) == sizeof(double), "SUNDIALS must be built with double");

/// Owns a SUNContext.
class SundialsContext {
 public:
  SundialsContext() { SUNContext_Create(nullptr, &ctx_); }
  ~SundialsContext() {
    if (ctx_ != nullptr) SUNContext_Free(&ctx_);
  }
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;
  operator SUNContext() const { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

/// The name of a CVODE return flag ("CV_CONV_FAILURE").
inline std::string CvodeFlagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string s = name != nullptr ? name : std::to_string(flag);
  free(name);
  return s;
}

}  // namespace highlift::sim::detail
