/* glsroad: a road description (spec/road.md), its geometry, the scene it
 * becomes, and the motion of a camera rig and other vehicles along it.
 *
 * World frame (the original system's, as in examples/demo): x LEFT, y UP,
 * z FORWARD, metres.  Lateral offsets are positive to the LEFT of the
 * road's centre line (the NURBS curve), looking along increasing distance.
 */
#ifndef GLS_ROAD_H
#define GLS_ROAD_H
#include <stddef.h>
#include <stdio.h>
#include "nurbs.h"

#define ROAD_MAX_LANES 16
#define ROAD_NAME_MAX 256
/* The largest road description read (spec/road.md): some 300,000 control
 * points; a wrong path (a device, a huge file) is refused after this. */
#define ROAD_MAX_FILE ((size_t)16 << 20)

/* What a description may ask for (spec/road.md, "Limits").  Counts that
 * follow from several keys (frames from duration and fps, vertices from
 * the length and max_segment, ...) are checked before anything is
 * generated, so no description makes glsroad run for hours or exhaust
 * memory. */
#define ROAD_MAX_FRAMES 1000000L          /* frames of the sequence            */
#define ROAD_MAX_SECONDS 10000.0          /* its length in time (1 ms body steps) */
#define ROAD_MAX_VEHICLES 256             /* 'vehicle' lines                   */
#define ROAD_VEHICLE_NAME_MAX 64          /* bytes, NUL included: an instance name (at most 64) */
#define ROAD_MAX_VEHICLE_POSES 10000000L  /* frames x vehicles                 */
#define ROAD_MAX_PROFILE_POINTS 256       /* points of one profile             */
#define ROAD_MAX_POINTS 65536             /* control points of the centre line */
#define ROAD_MAX_VERTICES 4194304L        /* scene vertices; lanes.txt points  */
#define ROAD_MAX_TREES 1048576L           /* trees placed, all 'trees' lines   */

enum { MARK_NONE, MARK_SOLID, MARK_DASHED, MARK_DOUBLE };

/* A piecewise-linear profile: values v[i] at abscissae x[i] (increasing),
 * constant beyond the last point. */
typedef struct {
    int by_time;       /* speed profiles: 1 = x is time (s), 0 = distance (m) */
    int n;
    size_t cap;
    double *x, *v;
    int line;          /* first line that defined it, for messages */
} road_profile;

typedef struct {
    char name[ROAD_VEHICLE_NAME_MAX];
    double lateral;    /* m, positive left of the centre line             */
    double start;      /* distance along the road at t = 0                */
    int oncoming;      /* drives towards decreasing distance              */
    char object[ROAD_NAME_MAX]; /* scene object drawn for it (info only)  */
    road_profile speed;
    int line;
} road_vehicle;

typedef struct {
    double every, offset, start;
    int sides;         /* 1 left, 2 right, 3 both */
    char object[ROAD_NAME_MAX]; /* empty: glsroad's own tree object */
    int line;
} road_trees;

typedef struct {
    const char *file;  /* for messages */
    const char *text;  /* the description, borrowed from road_parse's caller */
    size_t len;        /* (keep it while errors may be reported)             */
    /* curve */
    int degree, npts;
    size_t ncap;
    double *pts, *w;   /* 3 per point; 1 per point */
    int nknots;
    double *knots;     /* NULL: clamped uniform */
    int line_points, line_knots;
    /* cross-section */
    int lanes;
    road_profile lane_width; /* by distance; one point = constant */
    double lane_width_const;
    int line_lane_width;
    double shoulder, verge;
    int marking[ROAD_MAX_LANES + 1];
    int marking_set[ROAD_MAX_LANES + 1];
    double marking_width, dash, gap, double_gap, marking_height;
    double bank_max, bank_speed;
    double tolerance, max_segment;
    int line_tolerance, line_max_segment, line_dash, line_fps; /* 0: default */
    double road_color[3], marking_color[3], verge_color[3];
    char road_texture[ROAD_NAME_MAX], verge_texture[ROAD_NAME_MAX];
    double road_tile, verge_tile;
    road_trees trees[16];
    int ntrees;
    /* motion */
    double fps;
    long frames;       /* -1: until the end of the road */
    double duration;
    int line_frames;
    double start;
    road_profile speed;
    double vehicle_lateral;
    double rig_height, rig_lateral, rig_forward, rig_pitch, rig_yaw, rig_roll; /* m, degrees */
    double body_freq, body_damping, accel_pitch, roughness, wheelbase;
    unsigned long seed;
    road_vehicle *veh;
    int nveh;
    size_t vcap;
} road_desc;

/* Parse a description (the keys: roads/road_keys.c).  On error: -1 and
 * "file:line:col: error: message", the line and a caret, in err.
 * road_desc_free releases what it allocated.  d keeps pointing at text
 * (for errors found later): keep it alive as long as d. */
int road_parse(const char *text, size_t len, const char *fname, road_desc *d, char *err, size_t errlen);
void road_desc_free(road_desc *d);
/* "file:LINE:COL: error: message", COL that of the key on LINE, then the
 * line and a caret (LINE 0: the last line), through base's located error
 * writer (gls_text_error).  Returns -1. */
int road_error_at(const road_desc *d, int line, char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* The keys a description may hold, as spec/road.md's Markdown tables
 * (glsroad --list-keys; roads/road_keys_doc.c). */
void road_list_keys(FILE *f);

/* ---- geometry ----------------------------------------------------------- */

typedef struct {
    const road_desc *d;
    nurbs c;
} road_geo;

/* The road's local frame at parameter u. */
typedef struct {
    double u, s;       /* parameter, distance along the centre line */
    rv3 C;             /* centre-line point                          */
    rv3 t;             /* unit tangent                               */
    rv3 lh, nh;        /* horizontal left, and t x ... up (unbanked) */
    rv3 l, n;          /* banked left (across the surface), normal   */
    double kappa;      /* signed horizontal curvature, > 0 curving left */
    double e;          /* cross slope (tan of the bank angle), > 0 left side low */
    double lw;         /* lane width here                            */
} road_frame;

int road_geo_init(road_geo *g, const road_desc *d, char *err, size_t errlen);
void road_geo_free(road_geo *g);
void road_frame_at(const road_geo *g, double u, road_frame *f);
void road_frame_at_s(const road_geo *g, double s, road_frame *f);
/* Lateral offset of lane boundary i (0 = leftmost) and of the road edges. */
double road_boundary_offset(const road_desc *d, const road_frame *f, int i);
double road_edge_offset(const road_desc *d, const road_frame *f); /* left edge; right is minus */

/* An edge of a band: P = C + (a * lane_width + b) * l + h * n + x * lh. */
typedef struct {
    double a, b, h, x;
} road_edge;
rv3 road_edge_point(const road_frame *f, const road_edge *e);

/* Stations (parameters) u0 = st[0] < ... < st[n-1] = u1 such that every
 * edge's polyline through the stations stays within the tolerance of the
 * true edge curve and no segment is longer than max_segment.  Returns the
 * count, -1 on out of memory, or -2 if more than ROAD_MAX_VERTICES stations
 * would be needed; *st is malloc'd. */
long road_stations(const road_geo *g, double u0, double u1, const road_edge *edges, int nedges, double **st);

/* Write the scene: DIR/road.scene and DIR/roadobj/ (Tree, Car).  Scene text
 * goes into the buffers given (the caller writes them atomically).  On
 * error -1 and the message in err; the caller frees the buffers' text
 * either way (what these functions free they leave NULL). */
typedef struct {
    char *text;
    size_t len;
} road_buf;
int road_emit_scene(const road_geo *g, road_buf *scene, road_buf *tree, road_buf *car, char *err, size_t errlen);
int road_emit_lanes(const road_geo *g, road_buf *out, char *err, size_t errlen);

/* The counts the description asks for (frames, sequence length, vehicle
 * poses, vertices, trees) against the limits above, before anything is
 * generated: 0, or -1 with the error at the key to change in err. */
int road_check_limits(const road_geo *g, char *err, size_t errlen);

/* ---- motion ------------------------------------------------------------- */

/* Distance travelled x, speed v and acceleration a at time t. */
void road_profile_motion(const road_profile *p, double t, double *x, double *v, double *a);
/* The time at which the distance travelled reaches X >= 0; INFINITY if
 * the speed drops to 0 before. */
double road_profile_time_to(const road_profile *p, double X);

typedef struct {
    long frame;
    double time;
    double s;          /* the vehicle's distance along the road */
    double R[9], T[3]; /* rig pose, camera-file convention: Pc = R P + T */
    double pitch, heave; /* body oscillation (rad, m) */
} road_pose;

/* Frames of the rig: count (or -1 with err), and a callback per frame. */
typedef int (*road_pose_fn)(void *ctx, const road_pose *p);
long road_run_trajectory(const road_geo *g, road_pose_fn fn, void *ctx, char *err, size_t errlen);

/* Vehicle v's object-to-world pose at time t (spec/road.md, "Other
 * vehicles"): P_world = M P_object + t.  Returns 1 if it is on the road,
 * 0 if beyond an end (then on along that end's tangent). */
int road_vehicle_pose(const road_geo *g, const road_vehicle *v, double time, double M[9], double t[3]);

/* Rotation matrix (camera-to-world or any proper rotation) to the unit
 * quaternion (x, y, z, w), w >= 0. */
void road_quat_from_R(const double R[9], double q[4]);

/* Write all motion outputs (trajectory.txt, poses_kitti.txt, poses_tum.txt,
 * vehicles.txt, and motion/NAME.txt into motion[i] for vehicle i) into the
 * buffers. */
int road_emit_motion(const road_geo *g, road_buf *traj, road_buf *kitti, road_buf *tum, road_buf *veh,
                     road_buf *motion, char *err, size_t errlen);

/* Shortest round-trip number text (roads/road_text.c): v, and v[0..n)
 * with sep between them. */
void road_num(FILE *f, double v);
void road_nums(FILE *f, const double *v, int n, const char *sep);
#endif
