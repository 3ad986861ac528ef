/* Preloaded (LD_PRELOAD) into the sanitizer build's test runs only: dlclose
 * does nothing, so the GL driver that libEGL loads at run time stays mapped
 * until the process exits. Unloaded, the pointers held in the driver's
 * globals vanish with it and LeakSanitizer reports the memory they owned as
 * leaks of an "<unknown module>" that no suppression can name. Mapped, its
 * memory stays reachable and its stacks keep their names. */
int dlclose(void *handle);

int dlclose(void *handle)
{
    (void)handle;
    return 0;
}
