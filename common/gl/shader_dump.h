/* With FS_SHADER_DUMP=DIR in the environment, every shader stage fluidsurf compiles is
 * also written to DIR exactly as it goes to glShaderSource (includes expanded, defines
 * inserted), for tests/glsl_validate.sh to check with the Khronos reference compiler.
 * Each source is DIR/<stage file>.<hash>.<vert|geom|frag|comp>; DIR/index.tsv gets one
 * line per compile: stage file, the defines (';'-joined), the dump's name, and the
 * program it belongs to ("PID.N": the process's Nth program). */
#ifndef FS_SHADER_DUMP_H
#define FS_SHADER_DUMP_H

/* Writes one stage's final source (stage: its shaders/ name; defines may be NULL);
 * first: the program's first stage, which starts a new program number. Does nothing
 * without FS_SHADER_DUMP; a failure to write is reported on stderr only. */
void fs_shader_dump(const char *stage, const char *defines, const char *source, int first);

#endif
