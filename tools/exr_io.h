/* exr_io.h - minimal scanline EXR read/write through the OpenEXR 3 Core (C) API.
 * Optional tooling: compiled only where OpenEXR is installed. Include after
 * <stdio.h>; link with `pkg-config --libs OpenEXR` (only OpenEXRCore is used).
 *
 *   mfx_exr_write: interleaved float pixels (1: Y, 3: RGB, 4: RGBA), top row
 *     first, stored as HALF (half != 0) or FLOAT, ZIP compressed, scanline.
 *   mfx_exr_read: a scanline (not tiled, not deep) EXR, part 0 of the file,
 *     half or float channels R,G,B(,A) or Y, sampling 1; returns interleaved
 *     float (RGB -> 3, RGBA -> 4, Y -> 1), top row first, over the data window.
 * Both return 0 on success, nonzero with a message on stderr on failure; a
 * failed read leaves *pixels NULL. */
#ifndef MFX_EXR_IO_H
#define MFX_EXR_IO_H

#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <openexr.h>

/* Upper bound on texels accepted by the reader (guards against absurd headers). */
#if defined(__GNUC__) || defined(__clang__)
#define MFX__EXR_FN static __attribute__((unused))
#else
#define MFX__EXR_FN static
#endif

#ifndef MFX_EXR_MAX_TEXELS
#define MFX_EXR_MAX_TEXELS ((int64_t)1 << 28)
#endif

MFX__EXR_FN int mfx__exr_fail(const char *path, const char *what, exr_result_t rv)
{
    if (rv != EXR_ERR_SUCCESS)
        fprintf(stderr, "exr: %s: %s (%s)\n", path ? path : "(null)", what, exr_get_default_error_message(rv));
    else
        fprintf(stderr, "exr: %s: %s\n", path ? path : "(null)", what);
    return 1;
}

/* Silences the library's own reporting; our messages name the failing step. */
MFX__EXR_FN void mfx__exr_quiet(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt; (void)code; (void)msg;
}

/* mfx_exr_write with the data window's top-left corner at (x0, y0) (display
 * window the same box). */
MFX__EXR_FN int mfx_exr_write_at(const char *path, const float *pixels, int width, int height, int channels, int half,
                                 int x0, int y0)
{
    static const char *names1[] = { "Y" }, *names4[] = { "R", "G", "B", "A" };
    const char **names = channels == 1 ? names1 : names4;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_encode_pipeline_t enc;
    exr_chunk_info_t cinfo;
    exr_result_t rv;
    int part = 0, c, lines = 0, started = 0, err = 0, y;
    const char *what = NULL;

    if (!path || !pixels || width < 1 || height < 1 || !(channels == 1 || channels == 3 || channels == 4) ||
        (int64_t)width * height > MFX_EXR_MAX_TEXELS || (int64_t)x0 + width - 1 > INT32_MAX ||
        (int64_t)y0 + height - 1 > INT32_MAX)
        return mfx__exr_fail(path, "invalid arguments", EXR_ERR_SUCCESS);
    memset(&enc, 0, sizeof enc);
    init.error_handler_fn = mfx__exr_quiet;
    rv = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv != EXR_ERR_SUCCESS) return mfx__exr_fail(path, "cannot open for writing", rv);
#define MFX__TRY(call, msg) do { rv = (call); if (rv != EXR_ERR_SUCCESS) { what = (msg); goto done; } } while (0)
    MFX__TRY(exr_add_part(ctx, "main", EXR_STORAGE_SCANLINE, &part), "add part");
    {
        exr_attr_box2i_t box;
        exr_attr_v2f_t center;
        memset(&center, 0, sizeof center);
        box.min.x = x0; box.min.y = y0; box.max.x = x0 + width - 1; box.max.y = y0 + height - 1;
        MFX__TRY(exr_initialize_required_attr(ctx, part, &box, &box, 1.0f, &center, 1.0f, EXR_LINEORDER_INCREASING_Y,
                                              EXR_COMPRESSION_ZIP), "header");
    }
    for (c = 0; c < channels; ++c)
        MFX__TRY(exr_add_channel(ctx, part, names[c], half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT,
                                 EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1), "add channel");
    MFX__TRY(exr_write_header(ctx), "write header");
    MFX__TRY(exr_get_scanlines_per_chunk(ctx, part, &lines), "scanlines per chunk");
    if (lines < 1) { what = "bad chunk height"; goto done; }
    for (y = 0; y < height; y += lines) {
        int i;
        MFX__TRY(exr_write_scanline_chunk_info(ctx, part, y0 + y, &cinfo), "chunk info");
        if (cinfo.start_y != y0 + y) { what = "unexpected chunk start"; goto done; }
        if (!started) {
            MFX__TRY(exr_encoding_initialize(ctx, part, &cinfo, &enc), "encoder init");
            started = 1;
        } else {
            MFX__TRY(exr_encoding_update(ctx, part, &cinfo, &enc), "encoder update");
        }
        /* The file sorts channels by name: match each by name to its slot. */
        for (i = 0; i < enc.channel_count; ++i) {
            exr_coding_channel_info_t *ch = &enc.channels[i];
            int slot = -1;
            for (c = 0; c < channels; ++c)
                if (strcmp(ch->channel_name, names[c]) == 0) slot = c;
            if (slot < 0) { what = "unexpected channel"; goto done; }
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4 * channels;
            ch->user_line_stride = 4 * channels * width;
            ch->encode_from_ptr = (const uint8_t *)(pixels + ((size_t)y * width) * channels + slot);
        }
        MFX__TRY(exr_encoding_choose_default_routines(ctx, part, &enc), "encoder routines");
        MFX__TRY(exr_encoding_run(ctx, part, &enc), "encode");
    }
done:
    if (started) exr_encoding_destroy(ctx, &enc);
    if (what) err = mfx__exr_fail(path, what, rv);
    rv = exr_finish(&ctx);
    if (!err && rv != EXR_ERR_SUCCESS) err = mfx__exr_fail(path, "finish", rv);
    return err;
}

MFX__EXR_FN int mfx_exr_write(const char *path, const float *pixels, int width, int height, int channels, int half)
{
    return mfx_exr_write_at(path, pixels, width, height, channels, half, 0, 0);
}

MFX__EXR_FN int mfx_exr_read(const char *path, float **pixels, int *width, int *height, int *channels)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_decode_pipeline_t dec;
    exr_chunk_info_t cinfo;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *chl = NULL;
    exr_storage_t storage;
    exr_result_t rv = EXR_ERR_SUCCESS;
    int64_t w64, h64;
    int w = 0, h = 0, nch = 0, lines = 0, started = 0, y, i, c, have[5] = { 0, 0, 0, 0, 0 };
    static const char *names[5] = { "R", "G", "B", "A", "Y" };
    float *out = NULL, *plane = NULL;
    const char *what = NULL;

    if (pixels) *pixels = NULL;
    if (!path || !pixels || !width || !height || !channels)
        return mfx__exr_fail(path, "invalid arguments", EXR_ERR_SUCCESS);
    memset(&dec, 0, sizeof dec);
    init.error_handler_fn = mfx__exr_quiet;
    rv = exr_start_read(&ctx, path, &init);
    if (rv != EXR_ERR_SUCCESS) { exr_finish(&ctx); return mfx__exr_fail(path, "cannot read EXR header", rv); }
    MFX__TRY(exr_get_storage(ctx, 0, &storage), "storage");
    if (storage != EXR_STORAGE_SCANLINE) { what = "only scanline (not tiled or deep) images are supported"; goto done; }
    MFX__TRY(exr_get_data_window(ctx, 0, &dw), "data window");
    w64 = (int64_t)dw.max.x - dw.min.x + 1;
    h64 = (int64_t)dw.max.y - dw.min.y + 1;
    if (w64 < 1 || h64 < 1 || w64 > INT32_MAX || h64 > INT32_MAX || w64 * h64 > MFX_EXR_MAX_TEXELS) {
        what = "data window empty or too large"; goto done;
    }
    w = (int)w64; h = (int)h64;
    MFX__TRY(exr_get_channels(ctx, 0, &chl), "channels");
    for (i = 0; chl && i < chl->num_channels; ++i)
        for (c = 0; c < 5; ++c)
            if (chl->entries[i].name.str && strcmp(chl->entries[i].name.str, names[c]) == 0) {
                if ((chl->entries[i].pixel_type != EXR_PIXEL_HALF && chl->entries[i].pixel_type != EXR_PIXEL_FLOAT) ||
                    chl->entries[i].x_sampling != 1 || chl->entries[i].y_sampling != 1) {
                    what = "channel not half/float or subsampled"; goto done;
                }
                have[c] = 1;
            }
    if (have[0] && have[1] && have[2]) nch = have[3] ? 4 : 3;
    else if (have[4]) nch = 1;
    else { what = "needs channels R,G,B or Y"; goto done; }
    if ((size_t)w * (size_t)h > SIZE_MAX / (sizeof(float) * (size_t)nch)) { what = "image too large"; goto done; }
    out = (float *)calloc((size_t)w * (size_t)h * (size_t)nch, sizeof(float));
    if (!out) { what = "out of memory"; goto done; }
    MFX__TRY(exr_get_scanlines_per_chunk(ctx, 0, &lines), "scanlines per chunk");
    if (lines < 1 || lines > 4096) { what = "bad chunk height"; goto done; }
    if (lines > h) lines = h;
    /* Decoded planar, one chunk at a time, then interleaved here: OpenEXR 3.1's
     * interleaving fast path for 4 half channels ignores the per-channel
     * pointers and stores the file's (alphabetical) order, A,B,G,R. */
    plane = (float *)malloc((size_t)w * (size_t)lines * (size_t)nch * sizeof(float));
    if (!plane) { what = "out of memory"; goto done; }
    for (y = dw.min.y; y <= dw.max.y; y += lines) {
        MFX__TRY(exr_read_scanline_chunk_info(ctx, 0, y, &cinfo), "chunk info");
        if (cinfo.start_y < dw.min.y || cinfo.height < 1 || cinfo.width != w ||
            cinfo.height > lines || (int64_t)cinfo.start_y + cinfo.height - 1 > dw.max.y) {
            what = "inconsistent chunk"; goto done;
        }
        if (!started) {
            MFX__TRY(exr_decoding_initialize(ctx, 0, &cinfo, &dec), "decoder init");
            started = 1;
        } else {
            MFX__TRY(exr_decoding_update(ctx, 0, &cinfo, &dec), "decoder update");
        }
        for (i = 0; i < dec.channel_count; ++i) {
            exr_coding_channel_info_t *ch = &dec.channels[i];
            int slot = -1;
            if (nch == 1) { if (strcmp(ch->channel_name, "Y") == 0) slot = 0; }
            else for (c = 0; c < nch; ++c) if (strcmp(ch->channel_name, names[c]) == 0) slot = c;
            if (slot < 0) { ch->decode_to_ptr = NULL; continue; }  /* skipped */
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4;
            ch->user_line_stride = 4 * w;
            ch->decode_to_ptr = (uint8_t *)(plane + (size_t)slot * (size_t)w * (size_t)lines);
        }
        MFX__TRY(exr_decoding_choose_default_routines(ctx, 0, &dec), "decoder routines");
        MFX__TRY(exr_decoding_run(ctx, 0, &dec), "decode");
        for (c = 0; c < nch; ++c) {
            const float *src = plane + (size_t)c * (size_t)w * (size_t)lines;
            float *dst = out + (size_t)(cinfo.start_y - dw.min.y) * (size_t)w * (size_t)nch + (size_t)c;
            size_t k, n = (size_t)w * (size_t)cinfo.height;
            for (k = 0; k < n; ++k) dst[k * (size_t)nch] = src[k];
        }
    }
#undef MFX__TRY
done:
    if (started) exr_decoding_destroy(ctx, &dec);
    exr_finish(&ctx);
    free(plane);
    if (what) {
        free(out);
        return mfx__exr_fail(path, what, rv);
    }
    *pixels = out; *width = w; *height = h; *channels = nch;
    return 0;
}

#endif /* MFX_EXR_IO_H */
