/* The output vocabulary (spec/outputs.md): one bit per file an output
 * makes, the words --outputs takes for them, and the formats of the image
 * and float files.  Below the writer and the player, so that every room
 * that names an output (the encoders, the writer, the plan, explain, the
 * library) takes it from here. */
#ifndef GLS_OUTPUT_TABLE_H
#define GLS_OUTPUT_TABLE_H

/* edges: the mixed-pixel map of an anti-aliased image (spec/antialiasing.md);
 * EDGES_AS_MASK: the same map under its old name mask_F.png (--outputs mask,
 * kept for one release).  disparity, disparity16: fx B / Zc of a rectified
 * pair, float and KITTI 16-bit PNG; depth16: 16-bit PNG of Zc * depth_scale
 * (spec/outputs.md "Disparity and 16-bit depth"); landmarks: the scene's
 * marks projected, as CSV (gt_landmarks.h); instance, class, coco, normals:
 * from the ground-truth pass (gt_pass.h, spec/outputs.md "Ground truth:
 * instances, classes, normals").  Each output is one bit: INSTANCE | CLASS
 * names the JSON table written with either. */
enum {
    GLS_OUT_IMAGE = 1,
    GLS_OUT_DEPTH = 2,
    GLS_OUT_POINTS = 4,
    GLS_OUT_EDGES = 8,
    GLS_OUT_EDGES_AS_MASK = 16,
    GLS_OUT_DISPARITY = 32,
    GLS_OUT_DISPARITY16 = 64,
    GLS_OUT_DEPTH16 = 128,
    GLS_OUT_INSTANCE = 256,
    GLS_OUT_CLASS = 512,
    GLS_OUT_COCO = 1024,
    GLS_OUT_NORMALS = 2048,
    GLS_OUT_LANDMARKS = 1u << 12
};
/* the outputs made from the mixed-pixel map, and from the centre pass's depth */
#define GLS_OUT_EDGE_MAPS (GLS_OUT_EDGES | GLS_OUT_EDGES_AS_MASK)
#define GLS_OUT_DISPARITIES (GLS_OUT_DISPARITY | GLS_OUT_DISPARITY16)
#define GLS_OUT_FROM_Z (GLS_OUT_DEPTH | GLS_OUT_POINTS | GLS_OUT_DISPARITIES | GLS_OUT_DEPTH16 | GLS_OUT_LANDMARKS)
/* the outputs made from the ground-truth pass's instance ids */
#define GLS_OUT_IDS (GLS_OUT_INSTANCE | GLS_OUT_CLASS | GLS_OUT_COCO)

/* depth16's scale by default: KITTI's metres * 256 (TUM's is 5000) */
#define GLS_DEPTH_SCALE_KITTI 256.0
#define GLS_DEPTH_SCALE_TUM 5000.0

/* Format of the float outputs (depth, disparity, normals, the image with
 * --image-format pfm): PFM, or NumPy .npy (out_npy.h). */
typedef enum { GLS_FLOAT_PFM = 0, GLS_FLOAT_NPY = 1 } gls_float_format;
/* flow (--outputs flow, spec/outputs.md "Optical flow"): three files from
 * frame t to the next of the trajectory, each its own bit: the KITTI PNG,
 * the Middlebury .flo and the mask of visible, occluded, out-of-view */
enum { GLS_OUT_FLOW = 1u << 20, GLS_OUT_FLOW_FLO = 1u << 21, GLS_OUT_FLOW_MASK = 1u << 22 };
#define GLS_OUT_FLOW_ALL (GLS_OUT_FLOW | GLS_OUT_FLOW_FLO | GLS_OUT_FLOW_MASK)
/* boxes (--outputs boxes, spec/outputs.md "Boxes"): KITTI labels and JSON */
enum { GLS_OUT_BOXES = 1u << 23, GLS_OUT_BOXES_JSON = 1u << 24 };
#define GLS_OUT_BOXES_ALL (GLS_OUT_BOXES | GLS_OUT_BOXES_JSON)

/* Image file format: 8-bit PNG, 16-bit PNG, float32 PFM ("PF", RGB). */
typedef enum { GLS_IMG_PNG8 = 0, GLS_IMG_PNG16 = 1, GLS_IMG_PFM = 2 } gls_image_format;

#endif
