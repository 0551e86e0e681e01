/* Shared by the libFuzzer harnesses (tests/fuzz/README.md): each input is written
 * to a file with the format's extension on a memory file system and handed to
 * the real reader by path, as a user's file would be. The readers' contract is
 * checked after each call: success, or a failure with one non-empty line of
 * printable text and an empty result. */
#ifndef FS_FUZZ_INPUT_H
#define FS_FUZZ_INPUT_H
#include "fs_error.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The path of this process's input file, ".../fsfuzz-PID.EXT", written with data. */
static const char *fs_fuzz_file(const uint8_t *data, size_t size, const char *ext)
{
    static char path[256];
    const char *dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    snprintf(path, sizeof path, "%s/fsfuzz-%d.%s", dir, (int)getpid(), ext);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        fprintf(stderr, "fuzz: cannot write %s\n", path);
        abort();
    }
    return path;
}

/* A failure's message must be one line of printable characters: abort otherwise,
 * so that libFuzzer keeps the input. */
static void fs_fuzz_check_message(int rc)
{
    if (rc == FS_OK) return;
    const char *m = fs_error_message();
    if (!*m) abort();
    for (const unsigned char *c = (const unsigned char *)m; *c; c++)
        if (*c < 0x20 || *c == 0x7f) {
            fprintf(stderr, "fuzz: error message has control character 0x%02x: %s\n", *c, m);
            abort();
        }
    if (rc != FS_ERR_INPUT && rc != FS_ERR_RUNTIME) {
        fprintf(stderr, "fuzz: unexpected code %d: %s\n", rc, m);
        abort();
    }
}

#endif
