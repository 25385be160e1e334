/* glsplay: render a compiled glscene bundle through OpenCV pinhole
 * cameras.  Its help text and the library's public API only: each
 * argument goes to glscene_play_arg, and glscene_play_run does the work
 * (lib/glscene_play.c, its options lib/glscene_play_args.c; docs/api.md
 * "How glsplay uses it"). */
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "glscene.h"
#include "stdout_check.h"
#include "usage.h"

static const char usage_text[] =
    "usage: glsplay BUNDLE.glsb --camera CAM [--camera CAM ...] -o OUTDIR [options]\n"
    "       glsplay BUNDLE.glsb [--camera CAM ...] --explain\n"
    "Renders the bundle's top-level object through each camera (spec/camera.md)\n"
    "and writes OUTDIR/NAME/image_000000.png, depth_000000.pfm, points_000000.ply\n"
    "where NAME is the camera file name without .cam (or .yml, .yaml: an OpenCV\n"
    "camera file, spec/camera.md).\n"
    "options:\n"
    "  --camera CAM, -c CAM   camera file (repeatable)\n"
    "  -o OUTDIR              output directory (created if missing)\n"
    "  --outputs LIST         comma-separated subset of image,depth,points,edges,\n"
    "                         disparity,disparity16,depth16,landmarks,instance,class,\n"
    "                         coco,normals,flow,boxes,coverage,edge_segments\n"
    "                         (default image,depth,points;\n"
    "                         spec/outputs.md):\n"
    "                         edges: edges_F.png, 255 where a pixel's anti-aliasing\n"
    "                         samples differ, i.e. it straddles an edge; it needs --aa N\n"
    "                         with N > 1 (mask: the same map as mask_F.png, its old\n"
    "                         name, for one release)\n"
    "                         disparity: fx B / Zc (float, +inf: no surface), for a\n"
    "                         rectified pair: exactly two cameras, the left one first;\n"
    "                         disparity16: the same as KITTI's 16-bit PNG (d * 256)\n"
    "                         depth16: 16-bit PNG of Zc * --depth-scale, 0: no surface\n"
    "                         landmarks: the scene's marks projected, landmarks_F.csv\n"
    "                         ground truth from the pixel centres, never blended:\n"
    "                         instance and class (16-bit PNG ids, with\n"
    "                         instances_F.json), coco (COCO JSON, RLE masks),\n"
    "                         normals (camera-frame, float)\n"
    "                         flow: optical flow to the trajectory's next frame,\n"
    "                         flow_F.png (KITTI), flow_F.flo (Middlebury),\n"
    "                         flowmask_F.png (0 no surface, 1 visible, 2 occluded,\n"
    "                         3 out of view), needs --trajectory\n"
    "                         boxes: each visible instance's 2D and 3D box,\n"
    "                         boxes_F.txt (KITTI labels), boxes_F.json\n"
    "                         coverage: each instance's exact visible area in each\n"
    "                         pixel, coverage_F.csv; needs exact coverage (--aa auto\n"
    "                         or exact)\n"
    "                         edge_segments: the visible edges as exact sub-pixel\n"
    "                         segments with the instance on each side,\n"
    "                         edge_segments_F.csv; needs exact coverage\n"
    "  --depth-scale S        depth16's scale: a positive number, kitti (256, the\n"
    "                         default) or tum (5000)\n"
    "  --float-format F       pfm (default) or npy (NumPy float32): the file format of\n"
    "                         depth, disparity, normals and the image with\n"
    "                         --image-format pfm\n"
    "  --size WxH             override every camera's width and height\n"
    "  --write-calib          also write the cameras' calibration (spec/outputs.md):\n"
    "                         NAME/calib_F.yml (OpenCV), calib_F.json per frame;\n"
    "                         calib.txt (KITTI) and NAME/camera_info.yaml (ROS)\n"
    "  --explain              print the rendering plan; without -o, render nothing\n"
    "  --times                at the end, the run's time line on stderr: load, build\n"
    "                         (pack), GL context, upload, plan, first draw, write\n"
    "  --background R,G,B     colour where no surface is, components 0..1 (default 0,0,0)\n"
    "  --occlusion M          occlusion culling: auto (default: when many boxes overlap\n"
    "                         in the view), on or off; the images are the same\n"
    "  --anisotropic N        anisotropic texture filtering up to N x, N in 1..16\n"
    "                         (default 1: off; sharper textures at grazing angles, but\n"
    "                         llvmpipe takes minutes per frame with it: make bench-aa)\n"
    "  --backend B            GL backend (spec/backends.md): auto (default: EGL where\n"
    "                         it gives a context, else OSMesa), egl (a GPU through\n"
    "                         EGL's device platform, else Mesa's surfaceless one),\n"
    "                         egl-device or egl-surfaceless (that platform only),\n"
    "                         osmesa; --explain says which one renders\n"
    "sequences (spec/road.md, \"Trajectory file\"):\n"
    "  --trajectory FILE      render every frame of FILE (glsroad's trajectory.txt, or\n"
    "                         KITTI or TUM poses); each camera file then gives that\n"
    "                         camera's pose relative to the rig\n"
    "  --frames A:B           only frames A..B-1 of the trajectory (also A:, :B, A), so\n"
    "                         consecutive ranges split a sequence across processes\n"
    "  --frame N              the frame number in the file names of a single render\n"
    "                         (default 0)\n"
    "  --motion NAME=FILE     move the named instance NAME by FILE's per-frame pose\n"
    "                         (object-to-parent; glsroad motion, KITTI or TUM rows;\n"
    "                         repeatable; spec/bundle.md section 9.3)\n"
    "  --flatten              draw every call inlined, as one flattened scene (the\n"
    "                         reference path; default: instanced, spec/bundle.md 9.3)\n"
    "  --resume               skip frames that are complete: every camera has the record\n"
    "                         NAME/.frame_F.done, written after its last file, for the\n"
    "                         same outputs and settings, and every file is there\n"
    "  --shard I/N            only the frames F with (F - A) mod N = I, A the first of\n"
    "                         --frames (0 without it): N processes, I = 0..N-1, render a\n"
    "                         sequence between them into one OUTDIR (a single render is\n"
    "                         shard 0's); --shard slurm: I and N from a Slurm job array's\n"
    "                         SLURM_ARRAY_TASK_ID, _COUNT (and _MIN, _STEP)\n"
    "anti-aliasing (spec/antialiasing.md):\n"
    "  --aa auto              the default: --aa exact where the run allows it (no\n"
    "                         shadows, no exposure or sensor effects, the box filter),\n"
    "                         else one sample a pixel (--aa 1); --explain says which\n"
    "  --aa exact             no samples: each pixel the exact visible areas times their\n"
    "                         colours (CPU, double; textures, lighting and the alpha\n"
    "                         test sampled at 64 points a pixel; a lens resamples the\n"
    "                         undistorted exact image; no shadows)\n"
    "  --aa N                 NxN samples per pixel, N in 1..4096 (1: one pass on the\n"
    "                         GPU, the fastest)\n"
    "  --samples M            M samples per pixel, M in 1..16777216 (lattice: any M;\n"
    "                         grid and stratified: a square)\n"
    "  --subpixel A           the N whose sample step is at most A pixels (A as 1/256 or\n"
    "                         0.004): N = ceil(1/A); grid and stratified Gaussian:\n"
    "                         ceil(6 sigma/A)\n"
    "  --filter box|gauss[:SIGMA]  box: plain average over the pixel (default);\n"
    "                         gauss: Gaussian weights, SIGMA px (default 0.5), window\n"
    "                         +-3 SIGMA\n"
    "  --pattern lattice|grid|stratified   sample points: a rank-1 lattice (default;\n"
    "                         drawn in one pass as a fine framebuffer), a regular grid\n"
    "                         (one pass with the box filter), or one per grid cell\n"
    "                         with deterministic jitter (one GL pass per sample)\n"
    "  --seed S               jitter seed for stratified (default 0)\n"
    "  --image-format F       png8 (default), png16 (16-bit PNG) or pfm (float32 RGB,\n"
    "                         image_F.pfm); 8 bits limit edges to ~1/256 px\n"
    "  --aa-tiles K           stratified and grid Gaussian: samples per GL pass\n"
    "                         (default: automatic)\n"
    "  --aa-memory MB         one-pass patterns: memory for the fine framebuffer's tiles\n"
    "                         and read-backs, MB in 16..1048576 (default 256)\n"
    "progress and time:\n"
    "  on a terminal, stderr shows progress: frames done, frames/s and time left for a\n"
    "  sequence, samples done for a long anti-aliased camera frame\n"
    "  --progress [bar]       show it even when stderr is not a terminal\n"
    "  --progress json        instead, one JSON object a line on stderr per camera frame\n"
    "                         written and one at the end, for cluster logs; also\n"
    "                         --progress=WORD.  A bare word after --progress (no . or /)\n"
    "                         is its value: bar or json\n"
    "  --writer-threads N     1 (default): encode and write a frame's files on a thread of\n"
    "                         their own while the next frame renders; 0: in turn, on one\n"
    "                         thread.  The files are the same either way\n"
    "  a render projected to take over a minute (timed on its first passes or frames)\n"
    "  prints the estimate on stderr first: \"glsplay: note: estimated render time ...\"\n"
    "  --help                 this text\n"
    "  --version              print \"glsplay VERSION\" and exit\n"
    "exit status: 0 success, 1 input error, 2 usage error\n";

#define usage_error(...) gls_usage_error("glsplay", " (try glsplay --help)\n", __VA_ARGS__)

int main(int argc, char **argv)
{
    gls_check_stdout_at_exit("glsplay");
    glscene_play *r = glscene_play_new();
    if (!r)
        return 1;
    glscene_error e;
    int rc = 0;
    /* progress on a terminal unless --progress says otherwise */
    if (isatty(2))
        glscene_play_arg(r, "--progress", NULL, &e);
    for (int i = 1; i < argc && !rc;) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            gls_stdout_text(usage_text);
            glscene_play_free(r);
            return 0;
        }
        if (strcmp(argv[i], "--version") == 0) {
            glscene_play_free(r);
            return gls_version("glsplay");
        }
        int k = glscene_play_arg(r, argv[i], i + 1 < argc ? argv[i + 1] : NULL, &e);
        if (k == -1)
            rc = usage_error("%s", glscene_play_message(r));
        else if (k < 0)
            fprintf(stderr, "glsplay: error: %s\n", glscene_play_message(r)), rc = 2;
        else
            i += k;
    }
    if (!rc && glscene_play_check(r, &e))
        rc = usage_error("%s", glscene_play_message(r));
    if (!rc)
        rc = glscene_play_run(r, stdout, stderr);
    /* the GL driver the run loaded registered exit handlers that flush
     * standard output (stdout_check.h): the check again, to run first */
    gls_stdout_check_rearm();
    glscene_play_free(r);
    return rc;
}
