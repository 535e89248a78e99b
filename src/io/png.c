/* PNG files via libpng's simplified API (png_image): no printing, messages
 * captured into isk_error, atomic writes through a temporary file. */
#include "iskra/png.h"

#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

isk_status isk_png_write(const isk_canvas *c, const char *path, isk_error *err)
{
    if (!c || !path)
        return isk_error_set(err, ISK_ERR_NULL, "png write: NULL canvas or path");
    if (!c->pixels || c->width <= 0 || c->height <= 0)
        return isk_error_set(err, ISK_ERR_SIZE, "png write: empty canvas (%dx%d)", c->width, c->height);
    if (c->stride > 0x7fffffff)
        return isk_error_set(err, ISK_ERR_SIZE, "png write: stride too large");

    /* Temporary name in the same directory, so rename() is atomic. */
    size_t n = strlen(path);
    char *tmp = malloc(n + 16);
    if (!tmp)
        return isk_error_set(err, ISK_ERR_NOMEM, "png write: out of memory");
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp.XXXXXX", 12);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        isk_status s = isk_error_set(err, ISK_ERR_IO, "%s: cannot create temporary file: %s", path,
                                     strerror(errno));
        free(tmp);
        return s;
    }
    /* mkstemp creates the file 0600; give the result the permissions of the
     * file it replaces, or the usual 0644 for a new one. */
    struct stat st;
    fchmod(fd, stat(path, &st) == 0 ? (st.st_mode & 07777) : 0644);
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        isk_status s = isk_error_set(err, ISK_ERR_IO, "%s: %s", path, strerror(errno));
        close(fd);
        unlink(tmp);
        free(tmp);
        return s;
    }

    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)c->width;
    img.height = (png_uint_32)c->height;
    img.format = PNG_FORMAT_RGBA;
    int ok = png_image_write_to_stdio(&img, f, 0, c->pixels, (png_int_32)c->stride, NULL);
    char msg[sizeof img.message];
    memcpy(msg, img.message, sizeof msg);
    png_image_free(&img);
    int flush_ok = fflush(f) == 0 && fsync(fileno(f)) == 0;
    int close_ok = fclose(f) == 0;
    if (!ok || !flush_ok || !close_ok) {
        isk_status s = isk_error_set(err, ISK_ERR_IO, "%s: %s", path,
                                     !ok ? msg : "write failed (disk full?)");
        unlink(tmp);
        free(tmp);
        return s;
    }
    if (rename(tmp, path) != 0) {
        isk_status s = isk_error_set(err, ISK_ERR_IO, "%s: cannot rename temporary file: %s", path,
                                     strerror(errno));
        unlink(tmp);
        free(tmp);
        return s;
    }
    free(tmp);
    return ISK_OK;
}

isk_status isk_png_read(isk_canvas *out, const char *path, isk_error *err)
{
    if (!out || !path)
        return isk_error_set(err, ISK_ERR_NULL, "png read: NULL canvas or path");
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "rb");
    if (!f)
        return isk_error_set(err, ISK_ERR_IO, "%s: %s", path, strerror(errno));

    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_stdio(&img, f)) {
        isk_status s = isk_error_set(err, ISK_ERR_FORMAT, "%s: %s", path, img.message);
        png_image_free(&img);
        fclose(f);
        return s;
    }
    if (img.width == 0 || img.height == 0 || img.width > ISK_CANVAS_MAX_DIM ||
        img.height > ISK_CANVAS_MAX_DIM) {
        png_image_free(&img);
        fclose(f);
        return isk_error_set(err, ISK_ERR_SIZE, "%s: image size %ux%u not supported", path,
                             (unsigned)img.width, (unsigned)img.height);
    }
    img.format = PNG_FORMAT_RGBA;
    isk_status s = isk_canvas_init(out, (int)img.width, (int)img.height);
    if (s != ISK_OK) {
        png_image_free(&img);
        fclose(f);
        return isk_error_set(err, s, "%s: %s", path, isk_status_str(s));
    }
    if (!png_image_finish_read(&img, NULL, out->pixels, (png_int_32)out->stride, NULL)) {
        s = isk_error_set(err, ISK_ERR_FORMAT, "%s: %s", path, img.message);
        png_image_free(&img);
        isk_canvas_free(out);
        fclose(f);
        return s;
    }
    png_image_free(&img);
    fclose(f);
    return ISK_OK;
}
