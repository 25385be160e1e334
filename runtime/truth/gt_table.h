/* The ids of the `instance` and `class` outputs (spec/outputs.md
 * "Instances and classes"): made once per run from the bundle and the
 * scene, so they are the same in every frame and camera of the run.
 *
 * Instance ids: 1 + the rank of the instance among the scene's instances
 * that draw something (an item), in call-path order (the scene's instance
 * order: depth first, calls in program order); 0 is the background.  Each
 * has its call path: the top object's name, then for each call down to the
 * instance " > OBJECT#k", k = which instance call of OBJECT this is in its
 * parent, counting from 1.
 *
 * Class ids: 1 + the rank of the class name, in strcmp order, among the
 * classes of those instances (gls_gt_class_of). */
#ifndef GLS_GT_TABLE_H
#define GLS_GT_TABLE_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"
#include "scene.h"

/* The most ids a 16-bit image holds. */
#define GLS_GT_MAX_IDS 65535u

typedef struct {
    uint32_t ninst;      /* the scene's instances                       */
    uint16_t *id;        /* per scene instance: its id, 0: draws nothing */
    uint32_t nids;       /* ids 1..nids                                  */
    /* per id - 1 */
    char **path;         /* "Scene > road.vegetation.Birch#3"            */
    char **name;         /* the instance's name, or NULL                 */
    char **object;       /* its object's name                            */
    uint16_t *class_id;  /* 1..nclasses                                   */
    char **classes;      /* class id - 1 -> name, sorted                 */
    uint32_t nclasses;
} gls_gt_table;

/* The package of an object name: the name up to its last '.'
 * (road.vegetation for road.vegetation.Birch; a specialised object's
 * values are not part of it), or the name itself when it has none.
 * Writes at most len bytes (with the NUL). */
void gls_gt_package_of(const char *object, char *buf, size_t len);

/* The class of scene instance i: the one its object's `class` gives (a
 * specialised object's is its template's: the same code), else the one
 * of its nearest caller whose object gives one (the parts a `Car` calls
 * are the car's), else its object's package.  names[oi], declared[oi]:
 * bundle object oi's name and the class it gives or NULL (arrays, so
 * that it works once the bundle is freed).  The one place a class is
 * decided.  Writes at most len bytes (with the NUL). */
void gls_gt_class_of(const gls_scene *s, uint32_t i, const char *const *names, const char *const *declared,
                     char *buf, size_t len);

/* Number the scene's instances (b: the bundle s was built from).  0; 1
 * when more than GLS_GT_MAX_IDS instances draw something (*count says how
 * many; nothing allocated); -1 out of memory. */
int gls_gt_table_build(gls_gt_table *t, const gls_bundle *b, const gls_scene *s, uint32_t *count);
void gls_gt_table_free(gls_gt_table *t);

#endif
