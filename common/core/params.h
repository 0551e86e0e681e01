/* Method parameters: each method declares a table of fs_param_def; values are
 * doubles (enums hold the choice index, bools 0/1). "--set METHOD.PARAM=VALUE"
 * strings are validated against the table. */
#ifndef FS_PARAMS_H
#define FS_PARAMS_H
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MAX_PARAMS 32

typedef enum { FS_PARAM_FLOAT, FS_PARAM_INT, FS_PARAM_BOOL, FS_PARAM_ENUM } fs_param_type;

typedef struct fs_param_def {
    const char *name;
    fs_param_type type;
    double def, min, max;   /* range for FLOAT/INT, inclusive */
    const char *choices;    /* ENUM: "a|b|c"; the value is the index */
    const char *help;       /* one line, with units */
} fs_param_def;

/* Parses text for def into *out. FS_ERR_INPUT with a message naming what on error. */
int fs_param_parse(const fs_param_def *def, const char *text, double *out, const char *what);
/* Formats a value for display and provenance ("0.5", "on", "blend"). */
void fs_param_format(const fs_param_def *def, double v, char *buf, int size);
/* Choice index of an ENUM by name, or -1. */
int fs_param_choice(const fs_param_def *def, const char *name);

#ifdef __cplusplus
}
#endif
#endif
