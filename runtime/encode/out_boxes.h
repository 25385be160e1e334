/* Encoders of the boxes files (spec/outputs.md "Boxes"): KITTI object
 * labels (boxes_F.txt) and JSON (boxes_F.json), from gt_boxes.h's boxes.
 * Numbers are the shortest text that reads back as the same double. */
#ifndef GLS_OUT_BOXES_H
#define GLS_OUT_BOXES_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"
#include "camera.h"
#include "gt_boxes.h"
#include "scene.h"

/* What the labels name: the bundle's object names (the bundle is freed
 * once the renderer has it) and the scene's instance tree. */
typedef struct {
    const gls_scene *scene;
    char **objects;   /* by bundle object index */
    char **declared;  /* likewise: the class each gives, or NULL      */
    uint32_t nobjects;
} gls_box_names;

/* 0, or -1 when out of memory. */
int gls_box_names_init(gls_box_names *nm, const gls_bundle *b, const gls_scene *s);
void gls_box_names_free(gls_box_names *nm);

/* The class of instance i (gls_gt_class_of): the one its object's or its
 * nearest caller's `class` gives, else its object's package ("objects"
 * for "objects.Box(red=1)"). */
void gls_box_class(const gls_box_names *nm, uint32_t i, char *buf, size_t len);

/* One KITTI label line a box: type truncated occluded alpha left top right
 * bottom h w l x y z rotation_y. */
int gls_encode_boxes_kitti(const gls_box *b, size_t n, const gls_box_names *nm, gls_buf *out);

/* The JSON: camera, frame, image size and every box with all of the
 * above plus its object, instance name, pixel counts and 8 corners. */
int gls_encode_boxes_json(const gls_box *b, size_t n, const gls_box_names *nm, const gls_camera *c,
                          const char *camera, uint32_t frame, gls_buf *out);

#endif
