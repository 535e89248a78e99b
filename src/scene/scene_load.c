/* SPDX-License-Identifier: MIT */
/* isk_scene_load: a scene by the path of its file or by a built-in scene's
 * name, and the names suggested for one that is neither. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "iskra/scene.h"
#include "scene/ini_read.h"

isk_status isk_scene_load(isk_effect_def *out, const char *name_or_path, isk_error *err)
{
    if (!out)
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL definition");
    if (!name_or_path) {
        isk_effect_def_init(out);
        return isk_error_set(err, ISK_ERR_NULL, "scene: NULL name");
    }
    struct stat st;
    if (stat(name_or_path, &st) == 0)
        return isk_scene_load_file(out, name_or_path, err);
    const char *text = isk_scene_builtin_text(name_or_path);
    if (text) {
        char label[ISK_NAME_MAX + 16];
        snprintf(label, sizeof label, "scenes/%s.ini", name_or_path);
        return isk_scene_load_string(out, text, label, err);
    }
    isk_effect_def_init(out);
    /* A path-looking name is a missing file; otherwise suggest a built-in. */
    if (strchr(name_or_path, '/') || strstr(name_or_path, ".ini"))
        return isk_error_set(err, ISK_ERR_IO, "%s: %s", name_or_path, strerror(ENOENT));
    /* Part of a name ("fig19", "campfire") names the built-ins containing
     * it, when they are few; otherwise the nearest name by spelling. */
    enum { MAX_HITS = 4 };
    const char *hits[MAX_HITS];
    int nhits = 0;
    const int nbuiltin = isk_scene_builtin_count();
    for (int i = 0; strlen(name_or_path) >= 3 && i < nbuiltin; i++)
        if (strstr(isk_scene_builtin_name(i), name_or_path)) {
            if (nhits < MAX_HITS)
                hits[nhits] = isk_scene_builtin_name(i);
            nhits++;
        }
    if (nhits >= 1 && nhits <= MAX_HITS) {
        char list[4 * (ISK_NAME_MAX + 8)] = "";
        for (int i = 0; i < nhits; i++) {
            size_t used = strlen(list);
            snprintf(list + used, sizeof list - used, "%s%s", i == 0 ? "" : i == nhits - 1 ? " or " : ", ",
                     hits[i]);
        }
        return isk_error_set(err, ISK_ERR_IO, "%s: no such file or built-in scene; did you mean %s?",
                             name_or_path, list);
    }
    const char *names[256];
    int n = 0;
    for (int i = 0; i < nbuiltin && n < 256; i++)
        names[n++] = isk_scene_builtin_name(i);
    const char *s = isk__ini_suggest(name_or_path, names, (size_t)n);
    if (s)
        return isk_error_set(err, ISK_ERR_IO, "%s: no such file or built-in scene; did you mean %s?",
                             name_or_path, s);
    return isk_error_set(err, ISK_ERR_IO, "%s: no such file or built-in scene (`iskra list` shows them)",
                         name_or_path);
}
