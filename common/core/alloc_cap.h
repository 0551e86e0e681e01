/* A bound on single allocations while a library (VTK, OpenVDB, OpenEXR through
 * OpenImageIO) reads a user's file. Those libraries size buffers from counts in the
 * file before reading the bytes (OpenVDB's blosc reader even from an uninitialised
 * size after a short read). While a cap is in force, an operator new on this thread
 * larger than the bound throws std::bad_alloc, which the adapter reports as a bad
 * file. The bound is what the file's bytes can unpack to (zlib's 1032:1, twice,
 * plus 256 MB: OpenImageIO reads through a fixed 64 MB buffer), never more than
 * the memory available. C++ builds only
 * (alloc_cap.cpp replaces the global operator new). */
#ifndef FS_ALLOC_CAP_H
#define FS_ALLOC_CAP_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Puts the cap for reading path in force; returns the previous one, for _end. */
size_t fs_alloc_cap_begin(const char *path);
void fs_alloc_cap_end(size_t previous);

#ifdef __cplusplus
}

namespace fs
{
// The cap for the scope of this object.
class AllocCap
{
  public:
    explicit AllocCap(const char *path) : saved_(fs_alloc_cap_begin(path)) {}
    ~AllocCap() { fs_alloc_cap_end(saved_); }
    AllocCap(const AllocCap &) = delete;
    AllocCap &operator=(const AllocCap &) = delete;

  private:
    size_t saved_;
};
} // namespace fs
#endif
#endif
