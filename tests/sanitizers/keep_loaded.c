// Preloaded (LD_PRELOAD) into the sanitized test processes by tools/run_sanitized_tests.sh. The Vulkan
// loader unloads lavapipe and the validation layer when an instance is destroyed; LeakSanitizer then
// reports their leaks at exit with no module name, which no suppression can match. This opens each
// library named in STIPPLE_KEEP_LOADED (':'-separated) once more with RTLD_NODELETE, so that it stays
// mapped and its leaks are suppressed by library (lsan.supp). RTLD_LOCAL keeps its symbols out of the
// global scope: the validation layer exports vkGetInstanceProcAddr, which must not interpose the
// loader's. Built without sanitizers, and inert in processes without ASan (the shell, Xvfb, ctest).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>

__attribute__((constructor)) static void keep_loaded(void) {
    if (!dlsym(RTLD_DEFAULT, "__asan_init")) return;
    const char* list = getenv("STIPPLE_KEEP_LOADED");
    if (!list) return;
    char path[4096];
    while (*list) {
        size_t n = strcspn(list, ":");
        if (n > 0 && n < sizeof path) {
            memcpy(path, list, n);
            path[n] = '\0';
            dlopen(path, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
        }
        list += n + (list[n] == ':');
    }
}
