// Sanitizer builds only: keeps Mesa's software DRI driver loaded for the whole process (the
// test programs and the kinema binary they start).
// EGL dlopens it and dlcloses it at eglTerminate; once its pages are unmapped, LeakSanitizer
// cannot see what the driver's globals still point to and reports the driver's own
// allocations as leaks from an "<unknown module>" that no suppression can name. With the
// driver resident (RTLD_NODELETE), those allocations stay reachable and nothing is reported
// (checked: the same tests then show only libOSMesa's suppressed allocations).
#if defined(KINEMA_UNDER_SANITIZER)  // the sanitizer suite's builds
#include <dlfcn.h>

namespace {

struct KeepMesaDriverLoaded {
  KeepMesaDriverLoaded() {
    static const char* const kPaths[] = {"/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so",
                                         "/usr/lib/x86_64-linux-gnu/dri/kms_swrast_dri.so",
                                         "/usr/lib/aarch64-linux-gnu/dri/swrast_dri.so", "/usr/lib64/dri/swrast_dri.so"};
    for (const char* path : kPaths) (void)dlopen(path, RTLD_LAZY | RTLD_NODELETE);  // absent: nothing to keep
  }
};
const KeepMesaDriverLoaded keepMesaDriverLoaded;

}  // namespace
#endif
