/* libFuzzer harness: the scene JSON parser (fs_scene_load). */
#include "fuzz_input.h"
#include "scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fs_scene s; /* large: not on the stack */
    fs_error_clear();
    fs_fuzz_check_message(fs_scene_load(&s, fs_fuzz_file(data, size, "json")));
    return 0;
}
