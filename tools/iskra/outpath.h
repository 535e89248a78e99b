/* SPDX-License-Identifier: MIT */
/* Output paths of the iskra commands: every command creates the missing
 * parent directories of what it writes (nothing assumes the working
 * directory is the repository), and refuses an output that is one of its
 * own inputs (`compare --diff a.png a.png b.png`, `render s.ini --out
 * s.ini`), so a typo never destroys a file the command was reading.
 *
 *     if (outpath_refuse_input("render", out, scene_path)) return 2;
 *     ...everything validated...
 *     if (outpath_make_parents("render", out)) return 1;
 *
 * Messages go to stderr as "iskra CMD: ..."; the functions return 0 when
 * all is well and nonzero after printing why. */
#ifndef ISKRA_TOOL_OUTPATH_H
#define ISKRA_TOOL_OUTPATH_H

/* mkdir -p DIR (0777 before the umask).  0, or nonzero after printing
 * "iskra CMD: cannot create directory D: reason". */
int outpath_make_dirs(const char *cmd, const char *dir);

/* mkdir -p of the directory part of PATH (nothing for a bare file name). */
int outpath_make_parents(const char *cmd, const char *path);

/* 1 when both paths name the same existing file (same device and inode,
 * so a symlink or another spelling of the path counts as the same). */
int outpath_same_file(const char *a, const char *b);

/* Nonzero (after printing "iskra CMD: refusing to overwrite the input
 * IN with the output OUT") when out is the same file as in.  NULL
 * arguments are never the same file. */
int outpath_refuse_input(const char *cmd, const char *out, const char *in);

#endif
