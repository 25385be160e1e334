/* The keys of a road description (road_keys.h): the table, in the order
 * of spec/road.md's tables, and the steps of the keys whose values are
 * more than a store into a field (a control point appended, a profile
 * point added, an element of an array started). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "road_keys.h"

/* destinations: a field of the description with its default, element i
   of an array of doubles, a field of a 'trees' line or of a vehicle (their
   defaults are their steps'), none */
#define D(f, def) offsetof(road_desc, f), sizeof(((road_desc *)0)->f), def
#define DI(f, i, def) offsetof(road_desc, f) + (i) * sizeof(double), sizeof(double), def
#define T(f) offsetof(road_trees, f), sizeof(((road_trees *)0)->f), 0
#define V(f) offsetof(road_vehicle, f), sizeof(((road_vehicle *)0)->f), 0
#define NOWHERE 0, 0, 0

#define NUM(what, dst) {RV_NUM, what, RR_ANY, 0, 0, NULL, NULL, dst}
#define POS(what, dst) {RV_NUM, what, RR_POS, 0, 0, NULL, NULL, dst}
#define NONNEG(what, dst) {RV_NUM, what, RR_NONNEG, 0, 0, NULL, NULL, dst}
#define RANGE(what, lo, hi, why, dst) {RV_NUM, what, RR_RANGE, lo, hi, why, NULL, dst}
#define WHOLE(what, lo, hi, dst) {RV_WHOLE, what, RR_ANY, lo, hi, NULL, NULL, dst}
#define NAME(what, dst) {RV_NAME, what, RR_ANY, 0, 0, NULL, NULL, dst}
#define WORD(what, words, dst) {RV_WORD, what, RR_ANY, 0, 0, NULL, words, dst}
#define FLAG(value, dst) {RV_FLAG, NULL, RR_ANY, value, 0, NULL, NULL, dst}
#define RAW(what) {RV_RAW, what, RR_ANY, 0, 0, NULL, NULL, NOWHERE}
#define COLOUR(f, i, def) RANGE("colour component", 0, 1, NULL, DI(f, i, def))
#define VEHICLE_NAME {RV_IDENT, "vehicle name", RR_ANY, 0, 0, NULL, NULL, V(name)}

/* ---- the keys' own steps ------------------------------------------------ */

static void *point_prepare(road_pctx *c, road_desc *d, char **a, int na)
{
    (void)a, (void)na;
    if (d->npts == ROAD_MAX_POINTS)
        return road_fail(c, NULL, "at most %d control points", ROAD_MAX_POINTS), NULL;
    size_t cap = d->ncap;
    if (gls_grow(&d->pts, &cap, (size_t)d->npts + 1, 3 * sizeof(double)))
        return road_fail(c, NULL, "out of memory"), NULL;
    double *w = gls_resize(d->w, cap, sizeof(double)); /* a weight per point */
    if (!w)
        return road_fail(c, NULL, "out of memory"), NULL;
    d->w = w;
    d->ncap = cap;
    return d;
}

static int point_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)base, (void)a;
    for (int i = 0; i < 3; i++)
        d->pts[3 * d->npts + i] = v[i].num;
    d->w[d->npts] = na == 4 ? v[3].num : 1;
    if (d->npts == 0)
        d->line_points = road_line(c);
    d->npts++;
    return 0;
}

static int knots_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)base, (void)a;
    d->knots = gls_resize(NULL, (size_t)na, sizeof(double));
    if (!d->knots)
        return road_fail(c, NULL, "out of memory");
    for (int i = 0; i < na; i++)
        d->knots[i] = v[i].num;
    d->nknots = na;
    return 0;
}

static int lane_width_at_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)base, (void)a, (void)na;
    return road_profile_add(c, &d->lane_width, v[0].num, v[1].num);
}

static const char *const MARKING_STYLES[] = {"solid", "dashed", "double", "none", NULL};

static int marking_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)base, (void)a, (void)na;
    static const int style[] = {MARK_SOLID, MARK_DASHED, MARK_DOUBLE, MARK_NONE}; /* of MARKING_STYLES */
    long b = v[0].whole; /* a later line for the boundary replaces an earlier */
    d->marking[b] = style[v[1].word];
    d->marking_set[b] = road_line(c);
    return 0;
}

static void *trees_prepare(road_pctx *c, road_desc *d, char **a, int na)
{
    (void)a, (void)na;
    if (d->ntrees == (int)(sizeof d->trees / sizeof d->trees[0]))
        return road_fail(c, NULL, "at most %d 'trees' lines", (int)(sizeof d->trees / sizeof d->trees[0])), NULL;
    road_trees *t = &d->trees[d->ntrees++]; /* an error anywhere drops the whole description */
    memset(t, 0, sizeof *t);
    t->sides = 3;
    t->line = road_line(c);
    return t;
}

static int duration_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)c, (void)base, (void)a, (void)na, (void)v;
    d->frames = -2; /* frames = round(duration * fps), resolved once fps is known */
    return 0;
}

/* A speed point "distance X V" or "time T V" (words a[0..2]) of key into
   profile p: all of a profile's points by distance or all by time. */
static int speed_point(road_pctx *c, const char *key, road_profile *p, char **a)
{
    static const char *const bases[] = {"distance", "time", NULL};
    static const road_val basis = WORD("speed basis", bases, NOWHERE);
    static const road_val by[2][2] = {
        {NONNEG("distance", NOWHERE),
         {RV_NUM, "speed", RR_POS, 0, 0, "by distance: the vehicle could never pass a point of speed 0", NULL, NOWHERE}},
        {NONNEG("time", NOWHERE), NONNEG("speed", NOWHERE)},
    };
    road_value b, x, v;
    if (road_value_parse(c, key, &basis, a[0], &b))
        return -1;
    if (p->n && p->by_time != b.word)
        return road_fail(c, NULL, "a speed profile is given either by distance or by time, not both");
    p->by_time = b.word;
    if (road_value_parse(c, key, &by[b.word][0], a[1], &x) || road_value_parse(c, key, &by[b.word][1], a[2], &v))
        return -1;
    return road_profile_add(c, p, x.num, v.num);
}

static int speed_at_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)base, (void)na, (void)v;
    return speed_point(c, "speed_at", &d->speed, a);
}

static road_vehicle *find_vehicle(road_desc *d, const char *name)
{
    for (int i = 0; i < d->nveh; i++)
        if (!strcmp(d->veh[i].name, name))
            return &d->veh[i];
    return NULL;
}

static void *vehicle_prepare(road_pctx *c, road_desc *d, char **a, int na)
{
    (void)na;
    static const road_val name = VEHICLE_NAME;
    road_value v;
    if (road_value_parse(c, "vehicle", &name, a[0], &v))
        return NULL;
    const road_vehicle *old = find_vehicle(d, a[0]);
    if (old) {
        char what[80];
        snprintf(what, sizeof what, "vehicle %s", a[0]);
        return road_twice(c, what, old->line), NULL;
    }
    if (d->nveh == ROAD_MAX_VEHICLES)
        return road_fail(c, NULL, "at most %d 'vehicle' lines", ROAD_MAX_VEHICLES), NULL;
    size_t cap = d->vcap;
    if (gls_grow(&d->veh, &cap, (size_t)d->nveh + 1, sizeof(road_vehicle)))
        return road_fail(c, NULL, "out of memory"), NULL;
    d->vcap = cap;
    road_vehicle *veh = &d->veh[d->nveh++];
    memset(veh, 0, sizeof *veh);
    veh->line = road_line(c);
    return veh;
}

static int vehicle_speed_finish(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v)
{
    (void)base, (void)na, (void)v;
    road_vehicle *veh = find_vehicle(d, a[0]);
    if (!veh)
        return road_fail(c, a[0], "unknown vehicle '%s' (define it with a 'vehicle' line first)", a[0]);
    return speed_point(c, "vehicle_speed", &veh->speed, a + 1);
}

/* ---- options ------------------------------------------------------------ */

static const road_opt TREES_OPTS[] = {
    {"left", NULL, FLAG(1, T(sides))},
    {"right", NULL, FLAG(2, T(sides))},
    {"both", NULL, FLAG(3, T(sides))},
    {"start", "S", NONNEG("start", T(start))},
    {"object", "NAME", NAME("object", T(object))},
    {NULL, NULL, RAW(NULL)},
};

static const road_opt VEHICLE_OPTS[] = {
    {"lateral", "L", NUM("lateral", V(lateral))},
    {"start", "S", NONNEG("start", V(start))},
    {"oncoming", NULL, FLAG(1, V(oncoming))},
    {"object", "NAME", NAME("object", V(object))},
    {NULL, NULL, RAW(NULL)},
};

/* ---- the table ---------------------------------------------------------- */

/* One value, given once, stored into the description. */
#define ONE(k, sec, vals, def, mean, v) \
    {.key = k, .section = sec, .values = vals, .deflt = def, .meaning = mean, .min = 1, .max = 1, .val = {v}}

const road_key road_keys[] = {
    {.key = "degree", .section = RS_CURVE, .values = "p, 1..9", .meaning = "degree of the NURBS curve", .min = 1,
     .max = 1, .repeat = RK_ONCE, .val = {WHOLE("degree", 1, NURBS_MAX_DEGREE, D(degree, 3))}},
    {.key = "point", .section = RS_CURVE, .values = "x y z [w]", .deflt = "",
     .meaning = "a control point, weight w > 0 (default 1); at least p + 1 points", .min = 3, .max = 4,
     .repeat = RK_MANY,
     .val = {NUM("coordinate", NOWHERE), NUM("coordinate", NOWHERE), NUM("coordinate", NOWHERE),
             POS("weight", NOWHERE)},
     .prepare = point_prepare, .finish = point_finish},
    {.key = "knots", .section = RS_CURVE, .values = "the knot vector: points + p + 1 numbers",
     .deflt = "clamped uniform on [0, 1]",
     .meaning = "the whole knot vector: non-decreasing, clamped (first and last p + 1 equal), interior "
                "multiplicity at most p",
     .min = 2, .max = -1, .repeat = RK_ONCE, .line_off = offsetof(road_desc, line_knots),
     .val = {NUM("knot", NOWHERE)}, .finish = knots_finish},
    ONE("lanes", RS_SECTION, "1..16", NULL, "number of lanes", WHOLE("lanes", 1, ROAD_MAX_LANES, D(lanes, 2))),
    {.key = "lane_width", .section = RS_SECTION, .values = "m", .deflt = NULL, .meaning = "constant lane width",
     .min = 1, .max = 1, .repeat = RK_ONCE, .excludes = "lane_width_at", .line_off = offsetof(road_desc, line_lane_width),
     .val = {POS("lane width", D(lane_width_const, 3.5))}},
    {.key = "lane_width_at", .section = RS_SECTION, .values = "distance width", .deflt = "",
     .meaning = "variable width: linear between these points (the first at distance 0), constant after the last",
     .min = 2, .max = 2, .repeat = RK_MANY, .excludes = "lane_width",
     .val = {NONNEG("distance", NOWHERE), POS("lane width", NOWHERE)}, .finish = lane_width_at_finish},
    ONE("shoulder", RS_SECTION, "m", NULL, "paved width beyond the outer boundaries, each side",
        NONNEG("shoulder", D(shoulder, 0.5))),
    ONE("verge", RS_SECTION, "m", NULL, "grass band beyond each road edge, horizontal (not banked), 0 = none",
        NONNEG("verge", D(verge, 0))),
    {.key = "marking", .section = RS_SECTION, .values = "boundary style",
     .times = "the last for a boundary counts",
     .deflt = "edges `solid`, inner `dashed`",
     .meaning = "style of boundary 0..lanes: `solid`, `dashed`, `double`, `none`", .min = 2, .max = 2,
     .val = {WHOLE("boundary index", 0, ROAD_MAX_LANES, NOWHERE), WORD("marking style", MARKING_STYLES, NOWHERE)},
     .finish = marking_finish},
    ONE("marking_width", RS_SECTION, "m", NULL, "width of a painted line", POS("marking width", D(marking_width, 0.12))),
    {.key = "dash", .section = RS_SECTION, .values = "dash gap", .deflt = NULL,
     .meaning = "dash and gap lengths (m), measured along the centre line, first dash at distance 0", .min = 2,
     .max = 2, .line_off = offsetof(road_desc, line_dash),
     .val = {POS("dash length", D(dash, 3)), POS("gap length", D(gap, 9))}},
    ONE("double_gap", RS_SECTION, "m", NULL, "gap between the two lines of a `double` marking",
        POS("double_gap", D(double_gap, 0.12))),
    ONE("marking_height", RS_SECTION, "m", NULL,
        "markings float this far above the surface (along its normal), so the depth test keeps them in front",
        NONNEG("marking height", D(marking_height, 0.01))),
    ONE("bank_max", RS_SECTION, "cross slope, 0..0.5", NULL,
        "largest superelevation (rise over run); 0 = flat road",
        RANGE("bank_max", 0, 0.5, "a cross slope, rise over run", D(bank_max, 0))),
    ONE("bank_speed", RS_SECTION, "m/s", NULL, "design speed for the superelevation",
        POS("bank_speed", D(bank_speed, 25))),
    {.key = "tolerance", .section = RS_CURVE, .values = "metres, >= 1e-6", .deflt = NULL,
     .meaning = "largest chordal deviation of any emitted edge from its true curve", .min = 1, .max = 1,
     .line_off = offsetof(road_desc, line_tolerance),
     .val = {{RV_NUM, "tolerance", RR_MIN, 1e-6, 0, "a micrometre: finer is beyond what the tessellation can meet",
              NULL, D(tolerance, 0.001)}}},
    {.key = "max_segment", .section = RS_CURVE, .values = "metres", .deflt = NULL,
     .meaning = "longest quad along the road (keeps triangles short for the rasteriser)", .min = 1, .max = 1,
     .line_off = offsetof(road_desc, line_max_segment), .val = {POS("max_segment", D(max_segment, 10))}},
    {.key = "road_color", .section = RS_SECTION, .values = "r g b in 0..1", .deflt = NULL,
     .meaning = "colour of the road surface (where it has no texture)", .min = 3, .max = 3,
     .val = {COLOUR(road_color, 0, 0.32), COLOUR(road_color, 1, 0.32), COLOUR(road_color, 2, 0.34)}},
    {.key = "marking_color", .section = RS_SECTION, .values = "r g b in 0..1", .deflt = NULL,
     .meaning = "colour of the markings", .min = 3, .max = 3,
     .val = {COLOUR(marking_color, 0, 0.95), COLOUR(marking_color, 1, 0.95), COLOUR(marking_color, 2, 0.9)}},
    {.key = "verge_color", .section = RS_SECTION, .values = "r g b in 0..1", .deflt = NULL,
     .meaning = "colour of the verges (where they have no texture)", .min = 3, .max = 3,
     .val = {COLOUR(verge_color, 0, 0.25), COLOUR(verge_color, 1, 0.45), COLOUR(verge_color, 2, 0.2)}},
    {.key = "road_texture", .section = RS_SECTION, .values = "NAME TILE", .deflt = "none",
     .meaning = "texture of the road surface (looked up by glsc like any texture), repeated every TILE metres",
     .min = 2, .max = 2, .val = {NAME("texture", D(road_texture, 0)), POS("texture tile size", D(road_tile, 0))}},
    {.key = "verge_texture", .section = RS_SECTION, .values = "NAME TILE", .deflt = "none",
     .meaning = "texture of the verges, repeated every TILE metres", .min = 2, .max = 2,
     .val = {NAME("texture", D(verge_texture, 0)), POS("texture tile size", D(verge_tile, 0))}},
    {.key = "trees", .section = RS_SECTION, .values = "EVERY OFFSET [left|right|both] [start S] [object NAME]",
     .deflt = "both, start 0, glsroad's own tree",
     .meaning = "a tree every EVERY metres of centre line, OFFSET metres beyond the road edge; NAME is any scene "
                "object (e.g. `road.vegetation.Birch` from scenelib), upright, origin at its foot, x left, z "
                "along the road; at most 16 lines",
     .min = 2, .max = -1, .repeat = RK_MANY,
     .val = {POS("tree spacing", T(every)), NONNEG("tree offset from the road edge", T(offset))},
     .opts = TREES_OPTS, .prepare = trees_prepare},
    {.key = "fps", .section = RS_MOTION, .values = "> 0", .deflt = NULL,
     .meaning = "frame rate; frame k is at time k / fps", .min = 1, .max = 1,
     .line_off = offsetof(road_desc, line_fps), .val = {POS("fps", D(fps, 25))}},
    {.key = "frames", .section = RS_MOTION, .values = "N", .deflt = "until the end of the road",
     .meaning = "number of frames; running past the road's end is an error", .min = 1, .max = 1,
     .repeat = RK_ONCE, .excludes = "duration", .line_off = offsetof(road_desc, line_frames),
     .val = {WHOLE("frames", 1, ROAD_MAX_FRAMES, D(frames, -1))}},
    {.key = "duration", .section = RS_MOTION, .values = "seconds", .deflt = "until the end of the road",
     .meaning = "length of the sequence: round(duration fps) frames", .min = 1, .max = 1,
     .repeat = RK_ONCE, .excludes = "frames",
     .line_off = offsetof(road_desc, line_frames), .val = {NONNEG("duration", D(duration, 0))},
     .finish = duration_finish},
    ONE("start", RS_MOTION, "m", NULL, "distance along the road at frame 0", NONNEG("start", D(start, 0))),
    {.key = "speed_at", .section = RS_MOTION, .values = "distance X V | time T V", .deflt = "required",
     .meaning = "speed profile points; the first at 0; all by distance or all by time; linear between points, "
                "constant after the last",
     .min = 3, .max = 3, .repeat = RK_MANY, .val = {RAW("basis"), RAW("X"), RAW("V")}, .finish = speed_at_finish},
    ONE("vehicle_lateral", RS_MOTION, "m", NULL,
        "the ego vehicle's lateral position (e.g. -1.75: centre of the right lane)",
        NUM("vehicle_lateral", D(vehicle_lateral, 0))),
    ONE("rig_height", RS_MOTION, "m", NULL, "height of the rig origin in the vehicle body frame",
        NUM("rig_height", D(rig_height, 1.5))),
    ONE("rig_lateral", RS_MOTION, "m", NULL, "lateral position of the rig origin in the body frame (positive left)",
        NUM("rig_lateral", D(rig_lateral, 0))),
    ONE("rig_forward", RS_MOTION, "m", NULL, "forward position of the rig origin in the body frame",
        NUM("rig_forward", D(rig_forward, 0))),
    ONE("rig_pitch", RS_MOTION, "degrees, -180..180", NULL, "rig orientation: pitch > 0 looks down",
        RANGE("rig_pitch", -180, 180, "degrees", D(rig_pitch, 0))),
    ONE("rig_yaw", RS_MOTION, "degrees, -180..180", NULL, "rig orientation: yaw > 0 turns right",
        RANGE("rig_yaw", -180, 180, "degrees", D(rig_yaw, 0))),
    ONE("rig_roll", RS_MOTION, "degrees, -180..180", NULL,
        "rig orientation: roll > 0 turns clockwise seen from behind",
        RANGE("rig_roll", -180, 180, "degrees", D(rig_roll, 0))),
    ONE("body_freq", RS_MOTION, "Hz", NULL, "natural frequency of the body's pitch and heave",
        POS("body_freq (Hz)", D(body_freq, 1.2))),
    ONE("body_damping", RS_MOTION, "ratio", NULL, "damping ratio of the body's pitch and heave",
        NONNEG("body_damping (damping ratio)", D(body_damping, 0.3))),
    ONE("accel_pitch", RS_MOTION, "degrees per m/s^2", NULL,
        "static pitch from longitudinal acceleration (braking dips the nose)",
        NUM("accel_pitch (degrees per m/s^2)", D(accel_pitch, 0))),
    ONE("roughness", RS_MOTION, "m rms", NULL, "road roughness that excites pitch and heave",
        NONNEG("roughness (m rms)", D(roughness, 0))),
    ONE("wheelbase", RS_MOTION, "m", NULL, "distance between the axles (pitch from roughness)",
        POS("wheelbase", D(wheelbase, 2.7))),
    ONE("seed", RS_MOTION, "0..2147483647", NULL, "seed of the roughness profile",
        WHOLE("seed", 0, 2147483647L, D(seed, 1))),
    {.key = "vehicle", .section = RS_MOTION, .values = "NAME [lateral L] [start S] [oncoming] [object OBJ]",
     .times = "once per NAME", .deflt = "",
     .meaning = "another vehicle: its lane (lateral offset), where it is at frame 0, its object; `oncoming` drives "
                "towards decreasing distance; at most 256; it gets a motion file and a named call (below)",
     .min = 1, .max = -1,
     .repeat = RK_KEYED, .val = {VEHICLE_NAME}, .opts = VEHICLE_OPTS, .prepare = vehicle_prepare},
    {.key = "vehicle_speed", .section = RS_MOTION, .values = "NAME distance X V | NAME time T V", .deflt = "",
     .meaning = "its speed profile (distance = its own distance travelled)", .min = 4, .max = 4,
     .repeat = RK_MANY, .val = {RAW("NAME"), RAW("basis"), RAW("X"), RAW("V")}, .finish = vehicle_speed_finish},
};
const size_t road_nkeys = sizeof road_keys / sizeof road_keys[0];
_Static_assert(sizeof road_keys / sizeof road_keys[0] <= ROAD_KEYS_MAX, "raise ROAD_KEYS_MAX");
