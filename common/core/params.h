/* Method parameters: each method declares a table of fs_param_def, one entry per
 * double field of its parameter struct (enums hold the choice index, bools 0/1).
 * "METHOD.PARAM=VALUE" strings (--set, scene files, the library) are split here and
 * validated against the table. */
#ifndef FS_PARAMS_H
#define FS_PARAMS_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MAX_PARAMS 32

typedef enum { FS_PARAM_FLOAT, FS_PARAM_INT, FS_PARAM_BOOL, FS_PARAM_ENUM } fs_param_type;

typedef struct fs_param_def {
    const char *name;
    size_t offset;          /* of the parameter's double in the method's struct */
    fs_param_type type;
    double def, min, max;   /* range for FLOAT/INT, inclusive */
    const char *choices;    /* ENUM: "a|b|c"; the value is the index */
    const char *help;       /* one line, with units */
} fs_param_def;

/* The first two members of a table entry: the name and offset of member `member`
 * of struct type `type`, so a parameter is always named like its field. The
 * sizeof term is 0, or a compile error when the member is not a double (the
 * fill writes doubles). */
#define FS_PARAM_FIELD(type, member) \
    #member, offsetof(type, member) + 0 * sizeof(char[_Generic(((type *)0)->member, double: 1, default: -1)])

/* One "METHOD.PARAM=VALUE" setting, split at its first '.' and its first '=' (after the '.'). */
typedef struct fs_param_setting {
    char method[64], param[64];
    const char *value; /* into the split text: everything after the '=' */
} fs_param_setting;

/* The one parser of "METHOD.PARAM=VALUE" (scenes, --set, sweeps, tests): FS_ERR_INPUT
 * with "TEXT: ..." when a part is missing or empty or a name is too long. */
int fs_param_split(const char *text, fs_param_setting *out);

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
