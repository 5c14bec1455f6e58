/* Internal: the lock of a run's output directory DIR, the stage where its files wait, and their
 * publication (docs/robustness.md). gd_run_dir (run_dir.c) keeps the run's files and their list;
 * this is where they live before they are published and how they are published.
 *
 * The stage is PARENT/.NAME.geardyn-stage beside DIR (fixed name, same filesystem), and a set
 * with a summary.json is published by exchanging the stage and DIR in one renameat2
 * (RENAME_EXCHANGE); the previous tree, now at the stage's name, is then removed. Where that
 * cannot be (gd_stage.fallback says why) the stage is DIR/.staging and the files are moved into
 * DIR one by one, summary.json last. */
#ifndef GD_OUTPUT_STAGE_H
#define GD_OUTPUT_STAGE_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_error.h"

typedef struct gd_stage {
    char dir[GD_PATH_MAX];        /* DIR as given */
    char parent[GD_PATH_MAX];     /* DIR's parent and name in it (a symbolic link resolved) */
    char name[256];
    char sname[300];              /* the stage's name in parent (beside DIR) */
    char path[GD_PATH_MAX + 320]; /* the stage: parent/sname, or DIR/.staging */
    int dir_fd;                   /* DIR, locked (flock) while the run lasts */
    int stage_fd;                 /* the stage, locked too: it becomes DIR when published */
    int parent_fd;                /* O_PATH; -1 when the stage is DIR/.staging and parent unknown */
    int made_dir;                 /* DIR did not exist before this run */
    int keep_old;                 /* a user's entry could not leave the previous tree: the next
                                   * run into DIR moves it (the tree stays at the stage's name) */
    char fallback[160];           /* "" when the set is published in one step, else why not */
} gd_stage;

/* mkdir -p DIR, lock it (a second run is refused: GD_ERR_IO), remove what a killed run left
 * (returning the user's files of a half-finished publication to DIR) and make the stage. */
gd_status gd_stage_make(gd_stage *s, const char *dir, gd_error *err);
/* Publish the stage's files (names, "sub/" for a directory): with summary.json among them the
 * previous result's files the set lacks go and DIR's other entries stay; without it the files
 * are moved in and nothing else changes. */
gd_status gd_stage_publish(gd_stage *s, const char *const *files, int nfiles, gd_error *err);
/* Remove the stage when not published (and DIR when this run made it and it is empty), unlock. */
void gd_stage_close(gd_stage *s, int published);

#endif
