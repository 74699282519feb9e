// Linked only into the sanitizer build's programs (GESTURA_KEEP_MODULES_LOADED, preset `sanitize`):
// dlclose does nothing, so modules stay mapped until the process ends. eglTerminate unloads Mesa's
// driver (dri/swrast_dri.so) before exit; LeakSanitizer then finds the blocks its globals held with
// nothing pointing at them and reports them from an "<unknown module>", a report no suppression can
// name. Kept mapped, those globals are roots again. It hides nothing of gestura's own heap: gestura
// unloads no module of its own (docs/reliability.md, section 5).
extern "C" int dlclose(void*) { return 0; }
