// Preloaded by scripts/asan.sh into the test processes: dlclose does nothing, so the Mesa driver
// that EGL loads (swrast_dri.so: gallium/llvmpipe + LLVM) stays mapped until exit. Mesa unloads it
// in eglTerminate while its globals still point at heap blocks it never frees (caches, LLVM state);
// unmapped, those blocks look leaked and their stacks point into an "<unknown module>", which no
// suppression can name. Kept loaded, they stay reachable and LeakSanitizer is quiet about them,
// while a block our code leaks is still reported. It changes nothing else: nothing is unloaded.
extern "C" int dlclose(void*) { return 0; }
