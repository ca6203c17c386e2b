// Mesa's OSMesa keeps the window-system buffers it allocates in OSMesaMakeCurrent after the
// context is destroyed (a few hundred bytes per context, Mesa 22.3). LeakSanitizer reads these
// suppressions by itself in sanitizer builds (PARKSIM_SANITIZE=ON); other builds ignore them.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
