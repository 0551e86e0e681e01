/* SIGINT and SIGTERM: the temporary files of outputs in progress (output_file.h)
 * are removed, the outputs already finished stay (each was renamed into place
 * whole), one line says what was finished (progress.h), and the process exits
 * 130 or 143 as a shell would report the signal. */
#ifndef FS_INTERRUPT_H
#define FS_INTERRUPT_H
#ifdef __cplusplus
extern "C" {
#endif

void fs_interrupt_install(void);

#ifdef __cplusplus
}
#endif
#endif
