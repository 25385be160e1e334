/* Encoders of the instance and class outputs (spec/outputs.md "Instances
 * and classes"), from one frame's ground-truth pass: inst[i] = scene
 * instance index + 1 of the surface at pixel i, 0 where none
 * (gt_pass.h), top row first; ids from the run's table (gt_table.h). */
#ifndef GLS_OUT_GT_H
#define GLS_OUT_GT_H

#include <stdint.h>
#include "buf.h"
#include "gt_table.h"

/* instance_F.png (klass = 0) or class_F.png (klass = 1): 16-bit grey PNG
 * of instance or class ids, 0 where no surface is. */
int gls_encode_ids_png(const uint32_t *inst, const gls_gt_table *t, int klass, uint32_t w, uint32_t h,
                       gls_buf *out);

/* The PNG's samples, n pixels (the library's instance and class arrays). */
void gls_ids16(const uint32_t *inst, const gls_gt_table *t, int klass, size_t n, uint16_t *px);
/* instances_F.json: the frame, camera, image size, every instance with
 * pixels (id, path, name if named, object, class, class_id, pixels) and
 * the class table. */
int gls_encode_instances_json(const uint32_t *inst, const gls_gt_table *t, uint32_t frame, const char *camera,
                              uint32_t w, uint32_t h, gls_buf *out);

/* coco_F.json: COCO's object-detection annotation format, one image
 * (id = frame, file_name = image), the class table as categories, one
 * annotation per instance with pixels: iscrowd 1, segmentation as
 * uncompressed RLE ({"size": [h, w], "counts": [...]}, column-major,
 * starting with a run of zeros), bbox [x, y, width, height] of its
 * pixels, area = its pixel count. */
int gls_encode_coco(const uint32_t *inst, const gls_gt_table *t, uint32_t frame, const char *image, uint32_t w,
                    uint32_t h, gls_buf *out);

#endif
