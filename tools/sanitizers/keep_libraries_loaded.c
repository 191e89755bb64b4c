/* Preloaded into the sanitizer stage's tests (tools/sanitize.sh): dlclose() that leaves every
 * library loaded. Mesa's EGL and OSMesa unload the llvmpipe driver in their exit handlers, which run
 * before LeakSanitizer's; the driver's memory still held then would be reported from an
 * "<unknown module>" that no suppression can name. Kept loaded, it is reported from libgallium and
 * friends, which tools/sanitizers/lsan.supp suppresses, while our code stays checked. */
int dlclose(void *handle) {
    (void)handle;
    return 0;
}
