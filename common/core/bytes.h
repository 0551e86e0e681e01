/* Byte order of file formats, written once: big-endian (BGEO, PNG chunks) and
 * little-endian (raw float32) 32-bit words from bytes. */
#ifndef FS_BYTES_H
#define FS_BYTES_H
#include <stdint.h>

static inline uint32_t fs_be32(const unsigned char *b)
{
    return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
}
static inline uint32_t fs_le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

#endif
