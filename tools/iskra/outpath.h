/* SPDX-License-Identifier: MIT */
/* Output paths of the iskra commands: every command creates the missing
 * parent directories of what it writes (nothing assumes the working
 * directory is the repository), and refuses, before it writes anything,
 * an output that is one of its inputs (the scene, a texture it read, the
 * images compare reads) or another of its own outputs (`--out a.gif
 * --state a.gif`, `--out d/frame_000004.png --out-dir d`), so a typo never
 * destroys a file the command was reading or silently loses an output.
 *
 *     outpath_plan plan = {"render"};
 *     outpath_output(&plan, out, "--out");
 *     outpath_series(&plan, dir, "frame_", ".png", every, last, "--out-dir");
 *     if (outpath_clash(&plan)) return 2;                   // outputs among themselves
 *     if (outpath_refuse(&plan, scene, "the scene")) return 2;  // each input
 *     outpath_remove_stale(&plan);            // what a killed run left
 *     ...everything validated...
 *     if (outpath_make_parents("render", out)) return 1;
 *
 * "The same file" is decided after resolving the paths: two names of one
 * existing file (a symlink, "./x", "d/../x", a hard link) are the same;
 * for files not yet there, the same directory and name.  A character
 * device is never the same file as anything: it is written through, not
 * replaced, so `--out /dev/null --state /dev/null` loses nothing.
 *
 * Messages go to stderr as "iskra CMD: ..."; the functions return 0 when
 * all is well and nonzero after printing why. */
#ifndef ISKRA_TOOL_OUTPATH_H
#define ISKRA_TOOL_OUTPATH_H

enum { OUTPATH_MAX_OUTPUTS = 8, OUTPATH_MAX_SERIES = 4 };

/* A numbered series DIR/PREFIX%06ldSUFFIX for f = 0, every, 2 every, ...
 * <= last (render's --out-dir frames, --state-every states). */
typedef struct outpath_series_def {
    const char *dir, *prefix, *suffix, *what;
    long every, last;
} outpath_series_def;

/* Everything one command writes ("-", standard output, is not a path). */
typedef struct outpath_plan {
    const char *cmd;
    int nout, nseries;
    const char *out[OUTPATH_MAX_OUTPUTS], *out_what[OUTPATH_MAX_OUTPUTS];
    outpath_series_def series[OUTPATH_MAX_SERIES];
} outpath_plan;

/* Adds an output (NULL or "-": nothing), named in messages by `what`
 * (the option that gives it, e.g. "--out"). */
void outpath_output(outpath_plan *p, const char *path, const char *what);

/* Adds a numbered series (dir NULL: nothing). */
void outpath_series(outpath_plan *p, const char *dir, const char *prefix, const char *suffix, long every, long last,
                    const char *what);

/* Nonzero (after printing which two) when two outputs of the plan are
 * the same file, or an output is a member of one of its series. */
int outpath_clash(const outpath_plan *p);

/* Nonzero (after printing "iskra CMD: refusing to overwrite the input IN
 * (what) with the output OUT (--opt)") when the plan would write over
 * the file `in`.  An input that is not a file (NULL, a built-in scene's
 * name) is never refused. */
int outpath_refuse(const outpath_plan *p, const char *in, const char *what);

/* Removes the temporaries that an earlier run, killed before it could
 * (SIGKILL, a crash, a power cut), left beside the plan's outputs:
 * OUT.tmp.XXXXXX and, in a series' directory, PREFIX*SUFFIX.tmp.XXXXXX,
 * each only when no running writer holds it (isk_outfile_remove_stale).
 * Says on stderr how many it removed, if any. */
void outpath_remove_stale(const outpath_plan *p);

/* The same for a single output: nonzero when out is the file in. */
int outpath_refuse_input(const char *cmd, const char *out, const char *in);

/* 1 when both paths name the same file (see above). */
int outpath_same_file(const char *a, const char *b);

/* mkdir -p DIR (0777 before the umask).  0, or nonzero after printing
 * "iskra CMD: cannot create directory D: reason". */
int outpath_make_dirs(const char *cmd, const char *dir);

/* mkdir -p of the directory part of PATH (nothing for a bare file name). */
int outpath_make_parents(const char *cmd, const char *path);

#endif
