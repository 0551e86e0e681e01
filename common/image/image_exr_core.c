/* EXR files through OpenEXR 3's C core library (OpenEXRCore), in every build:
 * linking OpenImageIO's module only to write them cost a render about 0.5 s of
 * start-up (docs/DESIGN.md, "Start-up"). Writes what OpenImageIO's writer wrote
 * before: one scanline part, 32-bit float channels under the caller's names (the
 * file keeps them sorted by name, readers look them up by name), zip compression
 * (16 lines a chunk; at zlib's fastest level, below) and the provenance as string attributes. Reads scanline
 * EXRs: every channel as float; tiled and deep ones go to the OpenImageIO module
 * (fs_read_image_oiio). */
#include "image_exr_core.h"
#include "fs_error.h"
#include "output_file.h"

#include <openexr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* OpenEXRCore reports through a callback; keep its last message for the one-line error. */
static _Thread_local char exr_msg[512];

static void on_exr_error(exr_const_context_t ctx, exr_result_t code, const char *msg)
{
    (void)ctx;
    snprintf(exr_msg, sizeof exr_msg, "%s", msg && *msg ? msg : exr_get_default_error_message(code));
}

static exr_context_initializer_t initializer(void)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_exr_error;
    exr_msg[0] = 0;
    return init;
}

/* The library's message for rc (the callback's, else the code's default text), one line. */
static const char *why(exr_result_t rc)
{
    if (!exr_msg[0]) snprintf(exr_msg, sizeof exr_msg, "%s", exr_get_default_error_message(rc));
    exr_msg[strcspn(exr_msg, "\n")] = 0;
    return exr_msg;
}

/* ---- writing ---- */

/* Channel c's name in the file: the caller's, or "C<c>" (as image_oiio.cpp names it) when it has none. */
static const char *channel_name(const fs_image *img, int c, char buf[16])
{
    const char *n = img->chnames ? img->chnames[c] : NULL;
    if (n && *n) return n;
    snprintf(buf, 16, "C%d", c);
    return buf;
}

static exr_result_t write_parts(exr_context_t f, const fs_image *img, const fs_attr *attrs, int nattrs)
{
    int part;
    exr_result_t rc = exr_add_part(f, "", EXR_STORAGE_SCANLINE, &part);
    if (!rc) rc = exr_initialize_required_attr_simple(f, part, img->w, img->h, EXR_COMPRESSION_ZIP);
    /* zlib's fastest level: a whole 1024x1024 render of the DualSPHysics frame to EXR took
     * 1.67 s of CPU on one thread against 2.22 s at zlib's default (6), and its file was 1.4%
     * larger (15.84 MB, not 15.61) */
    if (!rc) rc = exr_set_zip_compression_level(f, part, 1);
    char fallback[16];
    for (int c = 0; !rc && c < img->nch; c++) {
        const char *n = channel_name(img, c, fallback);
        /* Perceptually logarithmic, OpenEXR's (and so OpenImageIO's) default. */
        rc = exr_add_channel(f, part, n, EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    }
    for (int i = 0; !rc && i < nattrs; i++)
        if (attrs[i].name && attrs[i].value) rc = exr_attr_set_string(f, part, attrs[i].name, attrs[i].value);
    /* OpenImageIO stamps every file with the time of writing (EXR's capDate): so do we. */
    char date[32];
    time_t now = time(NULL);
    struct tm tm;
    if (!rc && localtime_r(&now, &tm) && strftime(date, sizeof date, "%Y:%m:%d %H:%M:%S", &tm))
        rc = exr_attr_set_string(f, part, "capDate", date);
    if (!rc) rc = exr_write_header(f);
    int32_t lines = 0;
    if (!rc) rc = exr_get_scanlines_per_chunk(f, part, &lines);
    exr_encode_pipeline_t enc;
    memset(&enc, 0, sizeof enc);
    int started = 0;
    size_t row = (size_t)img->w * img->nch;
    for (int y = 0; !rc && y < img->h; y += lines) {
        exr_chunk_info_t ci;
        rc = exr_write_scanline_chunk_info(f, part, y, &ci);
        if (!rc) rc = started ? exr_encoding_update(f, part, &ci, &enc) : exr_encoding_initialize(f, part, &ci, &enc);
        if (rc) break;
        for (int k = 0; k < enc.channel_count; k++) {
            exr_coding_channel_info_t *ch = &enc.channels[k];
            /* The file sorts channels by name: find ours. Duplicate names keep the first. */
            int c = 0;
            char tmp[16];
            for (c = 0; c < img->nch; c++)
                if (!strcmp(channel_name(img, c, tmp), ch->channel_name)) break;
            if (c == img->nch) c = 0;
            ch->encode_from_ptr = (const uint8_t *)(img->pix + (size_t)(ci.start_y) * row + c);
            ch->user_pixel_stride = (int32_t)(img->nch * sizeof(float));
            ch->user_line_stride = (int32_t)(row * sizeof(float));
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = sizeof(float);
        }
        if (!started) rc = exr_encoding_choose_default_routines(f, part, &enc);
        started = 1;
        if (!rc) rc = exr_encoding_run(f, part, &enc);
    }
    if (started) exr_encoding_destroy(f, &enc);
    return rc;
}

int fs_write_exr(const char *path, const fs_image *img, const fs_attr *attrs, int nattrs)
{
    if (!img || img->w <= 0 || img->h <= 0 || img->nch <= 0 || !img->pix)
        return fs_fail(FS_ERR_INPUT, "%s: no image to write", path);
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    exr_context_initializer_t init = initializer();
    exr_context_t f = NULL;
    exr_result_t er = exr_start_write(&f, tmp, EXR_WRITE_FILE_DIRECTLY, &init);
    if (!er) er = write_parts(f, img, attrs, nattrs);
    exr_result_t fin = f ? exr_finish(&f) : EXR_ERR_SUCCESS;
    if (!er) er = fin;
    if (er) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: %s", path, why(er));
    }
    return fs_output_end(path, tmp, 1);
}

/* ---- reading ---- */

static int open_read(const char *path, exr_context_t *f)
{
    exr_context_initializer_t init = initializer();
    init.flags |= EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
    exr_result_t er = exr_start_read(f, path, &init);
    if (er) {
        if (*f) exr_finish(f);
        return fs_fail(FS_ERR_INPUT, "%s: %s", path, why(er));
    }
    return FS_OK;
}

/* Output order: R, G, B, A first (as OpenImageIO lists them), then the file's order. */
static int channel_rank(const char *n)
{
    static const char *const first[] = {"R", "G", "B", "A"};
    for (int i = 0; i < 4; i++)
        if (!strcmp(n, first[i])) return i;
    return 4;
}

/* The part's layout: scanline storage, its data window and channels, refused as bad input
 * before anything is allocated when a corrupt or hostile header declares too much. */
static int read_layout(exr_context_t f, const char *path, exr_attr_box2i_t *dw, const exr_attr_chlist_t **chl)
{
    exr_storage_t st;
    exr_result_t er = exr_get_storage(f, 0, &st);
    if (!er) er = exr_get_data_window(f, 0, dw);
    if (!er) er = exr_get_channels(f, 0, chl);
    if (er) return fs_fail(FS_ERR_INPUT, "%s: %s", path, why(er));
    if (st != EXR_STORAGE_SCANLINE)
        return fs_fail(FS_ERR_INPUT, "%s: only scanline EXR files are read (this one is tiled or deep)", path);
    int64_t w = (int64_t)dw->max.x - dw->min.x + 1, h = (int64_t)dw->max.y - dw->min.y + 1;
    int nch = *chl ? (*chl)->num_channels : 0;
    if (w <= 0 || h <= 0 || nch <= 0) return fs_fail(FS_ERR_INPUT, "%s: image has no pixels", path);
    if (w > (1 << 20) || h > (1 << 20) || w * h > ((int64_t)1 << 31) ||
        (uint64_t)(w * h) > SIZE_MAX / sizeof(float) / (uint64_t)nch)
        return fs_fail(FS_ERR_INPUT, "%s: image of %lldx%lld is too large", path, (long long)w, (long long)h);
    /* what the header declares must be what the file's bytes can unpack to (zlib: at most 1032:1) */
    if (fs_image_fits_file(path, (double)w, (double)h, nch)) return FS_ERR_INPUT;
    if (nch > 1024) return fs_fail(FS_ERR_INPUT, "%s: %d channels (at most 1024 are read)", path, nch);
    return FS_OK;
}

/* order[k]: the file's channel k goes to output channel order[k]. */
static int channel_order(const exr_attr_chlist_t *chl, const char *path, int *order)
{
    int nch = chl->num_channels, next = 0;
    for (int rank = 0; rank <= 4; rank++)
        for (int k = 0; k < nch; k++) {
            int r = channel_rank(chl->entries[k].name.str);
            if (r == rank) order[k] = next++;
            if (chl->entries[k].x_sampling != 1 || chl->entries[k].y_sampling != 1)
                return fs_fail(FS_ERR_INPUT, "%s: subsampled channel '%s' is not read", path, chl->entries[k].name.str);
        }
    return FS_OK;
}

static int alloc_image(fs_image *img, const exr_attr_box2i_t *dw, const exr_attr_chlist_t *chl, const int *order,
                       const char *path)
{
    int w = dw->max.x - dw->min.x + 1, h = dw->max.y - dw->min.y + 1, nch = chl->num_channels;
    img->w = w;
    img->h = h;
    img->nch = nch;
    img->pix = malloc((size_t)w * h * nch * sizeof(float));
    img->chnames = calloc((size_t)nch, sizeof(char *));
    int ok = img->pix && img->chnames;
    for (int k = 0; ok && k < nch; k++) ok = (img->chnames[order[k]] = strdup(chl->entries[k].name.str)) != NULL;
    if (!ok) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for a %dx%dx%d image", path, w, h, nch);
    return FS_OK;
}

/* Points each decoded channel of the chunk at its place in img (NULL: a channel not read). */
static void point_channels(exr_decode_pipeline_t *dec, const exr_attr_chlist_t *chl, const int *order, float *first_row,
                           const fs_image *img)
{
    size_t row = (size_t)img->w * img->nch;
    for (int k = 0; k < dec->channel_count; k++) {
        exr_coding_channel_info_t *ch = &dec->channels[k];
        int c = -1;
        for (int j = 0; j < img->nch && c < 0; j++)
            if (!strcmp(chl->entries[j].name.str, ch->channel_name)) c = order[j];
        if (c < 0) {
            ch->decode_to_ptr = NULL;
            continue;
        }
        ch->decode_to_ptr = (uint8_t *)(first_row + c);
        ch->user_pixel_stride = (int32_t)(img->nch * sizeof(float));
        ch->user_line_stride = (int32_t)(row * sizeof(float));
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = sizeof(float);
    }
}

/* Decodes the part chunk by chunk into img's pixels, every channel as float. */
static exr_result_t decode_chunks(exr_context_t f, const exr_attr_box2i_t *dw, const exr_attr_chlist_t *chl,
                                  const int *order, fs_image *img)
{
    int32_t lines = 0;
    exr_result_t er = exr_get_scanlines_per_chunk(f, 0, &lines);
    exr_decode_pipeline_t dec;
    memset(&dec, 0, sizeof dec);
    int started = 0;
    for (int64_t y = dw->min.y; !er && y <= dw->max.y; y += lines) {
        exr_chunk_info_t ci;
        er = exr_read_scanline_chunk_info(f, 0, (int)y, &ci);
        if (!er) er = started ? exr_decoding_update(f, 0, &ci, &dec) : exr_decoding_initialize(f, 0, &ci, &dec);
        if (er) break;
        point_channels(&dec, chl, order, img->pix + (size_t)(ci.start_y - dw->min.y) * img->w * img->nch, img);
        if (!started) er = exr_decoding_choose_default_routines(f, 0, &dec);
        started = 1;
        if (!er) er = exr_decoding_run(f, 0, &dec);
    }
    if (started) exr_decoding_destroy(f, &dec);
    return er;
}

static int read_pixels(exr_context_t f, const char *path, fs_image *img)
{
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *chl = NULL;
    int order[1024];
    int rc = read_layout(f, path, &dw, &chl);
    if (!rc) rc = channel_order(chl, path, order);
    if (!rc) rc = alloc_image(img, &dw, chl, order, path);
    if (rc) return rc;
    exr_result_t er = decode_chunks(f, &dw, chl, order, img);
    if (er) return fs_fail(FS_ERR_INPUT, "%s: %s", path, why(er));
    return FS_OK;
}

int fs_exr_is_scanline(const char *path)
{
    exr_context_t f = NULL;
    if (open_read(path, &f)) return -1;
    exr_storage_t st;
    exr_result_t er = exr_get_storage(f, 0, &st);
    if (er) fs_fail(FS_ERR_INPUT, "%s: %s", path, why(er));
    exr_finish(&f);
    return er ? -1 : st == EXR_STORAGE_SCANLINE;
}

int fs_exr_read(const char *path, fs_image *img)
{
    memset(img, 0, sizeof *img);
    exr_context_t f = NULL;
    int rc = open_read(path, &f);
    if (rc) return rc;
    rc = read_pixels(f, path, img);
    exr_finish(&f);
    if (rc) {
        char msg[1024];
        snprintf(msg, sizeof msg, "%s", fs_error_message());
        fs_image_free(img);
        return fs_fail(rc, "%s", msg);
    }
    return FS_OK;
}

int fs_exr_read_attr(const char *path, const char *name, char *buf, int size)
{
    if (size > 0) buf[0] = 0;
    exr_context_t f = NULL;
    if (open_read(path, &f)) return -1;
    /* OpenImageIO reports the compression as a string attribute too ("zip", ...). */
    exr_compression_t comp;
    if (!strcmp(name, "compression") && exr_get_compression(f, 0, &comp) == EXR_ERR_SUCCESS) {
        static const char *const names[] = {"none",  "rle", "zips", "zip",  "piz",
                                            "pxr24", "b44", "b44a", "dwaa", "dwab"};
        int known = (unsigned)comp < sizeof names / sizeof names[0];
        if (known && size > 0) snprintf(buf, (size_t)size, "%s", names[comp]);
        exr_finish(&f);
        return known;
    }
    const exr_attribute_t *a = NULL;
    int found = exr_get_attribute_by_name(f, 0, name, &a) == EXR_ERR_SUCCESS && a && a->type == EXR_ATTR_STRING;
    if (found && size > 0) snprintf(buf, (size_t)size, "%s", a->string->str ? a->string->str : "");
    exr_finish(&f);
    return found;
}

int fs_exr_read_provenance(const char *path, fs_provenance *out)
{
    static const char prefix[] = "fluidsurf:";
    out->n = 0;
    exr_context_t f = NULL;
    int32_t count = 0;
    if (open_read(path, &f)) return -1;
    if (exr_get_attribute_count(f, 0, &count) != EXR_ERR_SUCCESS) count = 0;
    for (int32_t i = 0; i < count; i++) {
        const exr_attribute_t *a = NULL;
        if (exr_get_attribute_by_index(f, 0, EXR_ATTR_LIST_FILE_ORDER, i, &a) != EXR_ERR_SUCCESS || !a) continue;
        if (a->type != EXR_ATTR_STRING || strncmp(a->name, prefix, sizeof prefix - 1)) continue;
        fs_provenance_set(out, a->name + sizeof prefix - 1, a->string->str ? a->string->str : "");
    }
    exr_finish(&f);
    return out->n;
}
