/* Method parameters: each method declares a table of fs_param_def, one entry per
 * field of its parameter struct, typed as the parameter is: double (FLOAT), int (INT),
 * an enum whose values are the choices' indices (ENUM), bool (BOOL). Values travel as
 * doubles (settings, sweeps, provenance) and take the field's type in the struct.
 * "METHOD.PARAM=VALUE" strings (the command line's, scene files', the library's) are split here and
 * validated against the table. */
#ifndef FS_PARAMS_H
#define FS_PARAMS_H
#include <stdbool.h>
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MAX_PARAMS 32

typedef enum { FS_PARAM_FLOAT, FS_PARAM_INT, FS_PARAM_BOOL, FS_PARAM_ENUM } fs_param_type;
/* The C type of a parameter's field (an enum's is int-sized: int or unsigned). */
typedef enum { FS_CTYPE_DOUBLE = 1, FS_CTYPE_INT, FS_CTYPE_BOOL } fs_param_ctype;

typedef struct fs_param_def {
    const char *name;
    size_t offset;        /* of the parameter's field in the method's struct */
    fs_param_ctype ctype; /* that field's C type, taken from its declaration */
    fs_param_type type;
    double def, min, max; /* range for FLOAT/INT, inclusive */
    const char *choices;  /* ENUM: "a|b|c"; the value is the index */
    const char *help;     /* one line, with units */
} fs_param_def;

/* The first three members of a table entry: the name, offset and C type of member `member`
 * of struct type `type`, so a parameter is always named like its field; a field that is not
 * a double, an int, an enum or a bool is a compile error. fs_method_params_fill checks the
 * C type against the entry's fs_param_type (FLOAT: double; INT, ENUM: int or enum; BOOL: bool). */
#define FS_PARAM_FIELD(type, member) #member, offsetof(type, member), FS_PARAM_CTYPE(((type *)0)->member)
/* The fs_param_ctype of an (unevaluated) field expression. */
#define FS_PARAM_CTYPE(field)                                                                                          \
    _Generic(field, double : FS_CTYPE_DOUBLE, int : FS_CTYPE_INT, unsigned : FS_CTYPE_INT, bool : FS_CTYPE_BOOL)
/* sizeof the field of that C type. */
size_t fs_param_ctype_size(fs_param_ctype c);

/* One "METHOD.PARAM=VALUE" setting, split at its first '.' and its first '=' (after the '.'). */
typedef struct fs_param_setting {
    char method[64], param[64];
    const char *value; /* into the split text: everything after the '=' */
} fs_param_setting;

/* The one parser of "METHOD.PARAM=VALUE" (scenes, the caller's settings, sweeps, tests): FS_ERR_INPUT
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
