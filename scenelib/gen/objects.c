/* Generator of the parametric objects of the scene library.
 * usage: gen_objects OUTROOT
 * Writes OUTROOT/<package path>/<Name>.scene for every object made here
 * (curves, straights and markings, signs, vehicles, calibration targets,
 * stereo surfaces, basic solids) and prints their paths, one a line.
 *
 * The scene language has no loops, so anything tessellated or repeated is
 * computed here and written as plain .scene text at build time, into
 * $(B)/scenelib/ (the Makefile; they are not committed);
 * tests/e2e/scenelib.sh runs this program again and checks that the
 * library directory holds exactly its output.
 *
 * A long file on purpose: it is a catalogue, one short writer per object
 * family over a few shared emitters, each read on its own.
 *
 * Conventions (scenelib/README.md): metres; y up; the ground is y = 0;
 * right-handed, so looking along +z, +x is on the LEFT.  The "front" of an
 * object faces -z: it is what a camera at negative z looking along +z sees.
 * Roads start at z = 0 and run along +z.
 *
 * Numbers are printed rounded to 1e-6 (a micrometre) with trailing zeros
 * dropped: exact to far better than a millimetre, short, and insensitive
 * to the last-bit differences libm's sin/cos may have between platforms.
 * Colours are printed to 1e-4 (finer than the 1/255 the player keeps). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mkdirs.h"

#define PI 3.14159265358979323846

/* ---- vectors ------------------------------------------------------------ */

typedef struct {
    double x, y, z;
} vec;

static vec V(double x, double y, double z)
{
    vec v = {x, y, z};
    return v;
}
static vec add(vec a, vec b) { return V(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec sub(vec a, vec b) { return V(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec mul(vec a, double k) { return V(a.x * k, a.y * k, a.z * k); }
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec cross(vec a, vec b) { return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static vec unit(vec a)
{
    double l = sqrt(dot(a, a));
    return l > 0 ? mul(a, 1 / l) : a;
}

/* ---- output ------------------------------------------------------------- */

static const char *outroot;
static char *body;        /* the current object's statements */
static size_t body_len;
static FILE *o;           /* writes into body */
static double lo[3], hi[3];
static char texnames[8][128];
static int ntex;
static int in_prim, oneline, line_has_items;

/* A number rounded to a micrometre, trailing zeros dropped, no "-0". */
static const char *num_d(double v, int decimals)
{
    static char ring[16][48];
    static int at;
    char *s = ring[at++ % 16];
    snprintf(s, 48, "%.*f", decimals, v);
    if (strchr(s, '.')) {
        size_t n = strlen(s);
        while (s[n - 1] == '0')
            s[--n] = 0;
        if (s[n - 1] == '.')
            s[--n] = 0;
    }
    if (strcmp(s, "-0") == 0)
        strcpy(s, "0");
    return s;
}
static const char *num(double v) { return num_d(v, 6); }

static void begin(void)
{
    for (int i = 0; i < 3; i++)
        lo[i] = INFINITY, hi[i] = -INFINITY;
    ntex = 0;
    o = open_memstream(&body, &body_len);
    if (!o) {
        perror("gen_objects: open_memstream");
        exit(1);
    }
}

static void out(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(o, fmt, ap);
    va_end(ap);
}

static void texture(const char *name)
{
    int seen = 0;
    for (int i = 0; i < ntex; i++)
        seen |= strcmp(texnames[i], name) == 0;
    if (!seen && ntex < 8)
        snprintf(texnames[ntex++], sizeof texnames[0], "%s", name);
    out("texture(\"%s\");\n", name);
}

static void prim(const char *kind, int one)
{
    out("%s {%s", kind, one ? "" : "\n");
    in_prim = 1, oneline = one, line_has_items = 0;
}

static void item_sep(void)
{
    if (oneline || line_has_items)
        out(" ");
    else
        out("  ");
    line_has_items = 1;
}

static void col(double r, double g, double b)
{
    r = r < 0 ? 0 : r > 1 ? 1 : r;
    g = g < 0 ? 0 : g > 1 ? 1 : g;
    b = b < 0 ? 0 : b > 1 ? 1 : b;
    item_sep();
    out("col(%s, %s, %s);", num_d(r, 4), num_d(g, 4), num_d(b, 4));
}

static void tex(double s, double t)
{
    item_sep();
    out("tex(%s, %s);", num(s), num(t));
}

/* A vertex; the bounding box is taken from the printed (rounded) values,
 * so it is exactly what the compiler will read. */
static void vert(vec p)
{
    const double c[3] = {p.x, p.y, p.z};
    item_sep();
    out("vert(");
    for (int i = 0; i < 3; i++) {
        const char *s = num(c[i]);
        double r = strtod(s, NULL);
        lo[i] = fmin(lo[i], r), hi[i] = fmax(hi[i], r);
        out("%s%s", s, i < 2 ? ", " : ");");
    }
    if (!oneline) {
        out("\n");
        line_has_items = 0;
    }
}

static void endprim(void)
{
    out(oneline ? " }\n" : "}\n");
    in_prim = 0;
}

/* Write the object: header comment (what, size from the bounding box,
 * origin and facing, textures), the machine-readable bbox line that the
 * tests check, then the statements. */
static void finish(const char *name, const char *what, const char *origin)
{
    fclose(o);
    char path[4096];
    int n = snprintf(path, sizeof path, "%s/", outroot);
    for (const char *p = name; *p && n < (int)sizeof path - 8; p++)
        path[n++] = *p == '.' ? '/' : *p;
    snprintf(path + n, sizeof path - (size_t)n, ".scene");
    if (gls_mkdir_parents(path)) {
        fprintf(stderr, "gen_objects: cannot create the directory of %s: %s\n", path, strerror(errno));
        exit(1);
    }
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "gen_objects: cannot write %s: %s\n", path, strerror(errno));
        exit(1);
    }
    fprintf(f, "// %s: ", name);
    /* the description, wrapped onto comment lines at its newlines */
    for (const char *p = what; *p; p++) {
        fputc(*p, f);
        if (*p == '\n')
            fputs("// ", f);
    }
    fprintf(f, "\n// Size: %s x %s x %s m (x, y, z), x %s..%s, y %s..%s, z %s..%s.\n", num(hi[0] - lo[0]),
            num(hi[1] - lo[1]), num(hi[2] - lo[2]), num(lo[0]), num(hi[0]), num(lo[1]), num(hi[1]), num(lo[2]),
            num(hi[2]));
    fprintf(f, "// Origin: ");
    for (const char *p = origin; *p; p++) {
        fputc(*p, f);
        if (*p == '\n')
            fputs("// ", f);
    }
    fprintf(f, "\n// Textures: ");
    if (!ntex)
        fprintf(f, "none");
    for (int i = 0; i < ntex; i++)
        fprintf(f, "%s%s", i ? ", " : "", texnames[i]);
    fprintf(f, ".\n// Generated by scenelib/gen/objects.c at build time; do not edit.\n");
    fprintf(f, "// bbox: %s %s %s %s %s %s\n", num(lo[0]), num(lo[1]), num(lo[2]), num(hi[0]), num(hi[1]), num(hi[2]));
    fwrite(body, 1, body_len, f);
    if (fclose(f)) {
        fprintf(stderr, "gen_objects: cannot write %s\n", path);
        exit(1);
    }
    free(body);
    body = NULL;
    printf("%s\n", path);
}

/* ---- shading -------------------------------------------------------------- */

/* The player has no lighting, so solids carry their shading in per-vertex
 * colours: brightness 0.62 + 0.3 n.L with a fixed light from above, the
 * left and the front.  Linear in n (not clamped like Lambert), so all six
 * faces of a box get different brightnesses and edges always show. */
static vec light(void) { return unit(V(0.35, 0.8, -0.5)); }
static double shade(vec n) { return 0.62 + 0.3 * dot(unit(n), light()); }

typedef struct {
    double r, g, b;
} rgb;

static rgb RGB(double r, double g, double b)
{
    rgb c = {r, g, b};
    return c;
}

static void scol(rgb c, vec n)
{
    double k = shade(n);
    col(c.r * k, c.g * k, c.b * k);
}

/* Newell's normal of a polygon, turned away from `inside`. */
static vec outward(const vec *p, int n, vec inside)
{
    vec nm = V(0, 0, 0), c = V(0, 0, 0);
    for (int i = 0; i < n; i++) {
        vec a = p[i], b = p[(i + 1) % n];
        nm = add(nm, V((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)));
        c = add(c, a);
    }
    c = mul(c, 1.0 / n);
    return dot(nm, sub(c, inside)) < 0 ? mul(nm, -1) : nm;
}

/* A flat-shaded convex face of a solid whose interior contains `inside`. */
static void face(const vec *p, int n, rgb c, vec inside)
{
    prim("poly", 1);
    scol(c, outward(p, n, inside));
    for (int i = 0; i < n; i++)
        vert(p[i]);
    endprim();
}

/* A face in one flat colour (no shading): markings, calibration targets. */
static void flatpoly(const vec *p, int n)
{
    prim("poly", 1);
    for (int i = 0; i < n; i++)
        vert(p[i]);
    endprim();
}

static void rect_y(double x0, double z0, double x1, double z1, double y)
{
    vec q[4] = {V(x0, y, z0), V(x1, y, z0), V(x1, y, z1), V(x0, y, z1)};
    flatpoly(q, 4);
}

static void rect_z(double x0, double y0, double x1, double y1, double z)
{
    vec q[4] = {V(x0, y0, z), V(x1, y0, z), V(x1, y1, z), V(x0, y1, z)};
    flatpoly(q, 4);
}

static void box(vec a, vec b, rgb c)
{
    vec in = mul(add(a, b), 0.5);
    vec f[6][4] = {
        {V(a.x, a.y, a.z), V(b.x, a.y, a.z), V(b.x, b.y, a.z), V(a.x, b.y, a.z)}, /* -z */
        {V(a.x, a.y, b.z), V(a.x, b.y, b.z), V(b.x, b.y, b.z), V(b.x, a.y, b.z)}, /* +z */
        {V(a.x, a.y, a.z), V(a.x, b.y, a.z), V(a.x, b.y, b.z), V(a.x, a.y, b.z)}, /* -x */
        {V(b.x, a.y, a.z), V(b.x, a.y, b.z), V(b.x, b.y, b.z), V(b.x, b.y, a.z)}, /* +x */
        {V(a.x, a.y, a.z), V(a.x, a.y, b.z), V(b.x, a.y, b.z), V(b.x, a.y, a.z)}, /* -y */
        {V(a.x, b.y, a.z), V(b.x, b.y, a.z), V(b.x, b.y, b.z), V(a.x, b.y, b.z)}, /* +y */
    };
    for (int i = 0; i < 6; i++)
        face(f[i], 4, c, in);
}

/* A convex polygon profile in the (z, y) plane, extruded along x from x0 to
 * x1: both caps and one flat-shaded quad per profile edge. */
static void prism_x(const double (*zy)[2], int n, double x0, double x1, rgb c)
{
    vec in = V((x0 + x1) / 2, 0, 0);
    for (int i = 0; i < n; i++)
        in.y += zy[i][1] / n, in.z += zy[i][0] / n;
    vec cap[16] = {{0, 0, 0}};
    if (n > 16) {
        fprintf(stderr, "gen_objects: profile with more than 16 points\n");
        exit(1);
    }
    for (int i = 0; i < n; i++)
        cap[i] = V(x0, zy[i][1], zy[i][0]);
    face(cap, n, c, in);
    for (int i = 0; i < n; i++)
        cap[i] = V(x1, zy[i][1], zy[i][0]);
    face(cap, n, c, in);
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        vec q[4] = {V(x0, zy[i][1], zy[i][0]), V(x0, zy[j][1], zy[j][0]), V(x1, zy[j][1], zy[j][0]),
                    V(x1, zy[i][1], zy[i][0])};
        face(q, 4, c, in);
    }
}

/* Is the profile convex (the player draws a poly as a fan)?  A generator
 * bug here would draw garbage, so stop. */
static void check_convex(const double (*p)[2], int n, const char *what)
{
    int sign = 0;
    for (int i = 0; i < n; i++) {
        const double *a = p[i], *b = p[(i + 1) % n], *c = p[(i + 2) % n];
        double z = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
        int s = z > 1e-12 ? 1 : z < -1e-12 ? -1 : 0;
        if (s && sign && s != sign) {
            fprintf(stderr, "gen_objects: profile of %s is not convex at point %d\n", what, (i + 1) % n);
            exit(1);
        }
        if (s)
            sign = s;
    }
}

/* A cylinder with axis from a to b (a and b the cap centres), radius r, n
 * sides: the side smooth-shaded (colour per vertex from its radial
 * normal), the caps flat.  u, w span the cap plane. */
static void cylinder(vec a, vec b, double r, int n, rgb c, int caps)
{
    vec ax = unit(sub(b, a));
    vec u = unit(cross(ax, fabs(ax.y) < 0.9 ? V(0, 1, 0) : V(1, 0, 0)));
    vec w = cross(ax, u);
    prim("qstrip", 0);
    for (int k = 0; k <= n; k++) {
        double t = 2 * PI * (k % n) / n;
        vec d = add(mul(u, cos(t)), mul(w, sin(t)));
        scol(c, d);
        vert(add(a, mul(d, r)));
        scol(c, d);
        vert(add(b, mul(d, r)));
    }
    endprim();
    for (int e = 0; caps && e < 2; e++) {
        vec cc = e ? b : a;
        prim("poly", 0);
        scol(c, e ? ax : mul(ax, -1));
        for (int k = 0; k < n; k++) {
            double t = 2 * PI * (e ? k : n - k) / n;
            vert(add(cc, mul(add(mul(u, cos(t)), mul(w, sin(t))), r)));
        }
        endprim();
    }
}

/* ---- road ----------------------------------------------------------------- */

/* Road marking standard followed (stated in scenelib/README.md): lane 3.50
 * m; longitudinal lines 0.12 m wide (German RMS narrow line, within the
 * Vienna Convention's 0.10-0.15 m); broken centre line 3 m dash, 6 m gap
 * (RMS urban "Leitlinie" 1:2); double line 2 x 0.12 m with a 0.12 m gap;
 * stop line 0.50 m; zebra crossing stripes 0.50 m wide, 0.50 m apart, 4 m
 * long.  Markings are 2 mm thick (top at y = 0.002) on a surface at y = 0,
 * so the depth test never sees them coplanar with the asphalt. */
#define LANE 3.5
#define LINE_W 0.12
#define DASH 3.0
#define GAP 6.0
#define EDGE_IN LANE               /* inner edge of the edge line */
#define EDGE_OUT (LANE + LINE_W)   /* outer edge of the edge line */
#define ROAD_HALF 3.75             /* asphalt half-width */
#define MARK_Y 0.002
#define TEX_TILE 2.0               /* road.tex.Asphalt covers 2 m x 2 m */

static void paint_white(void)
{
    out("notexture;\ntexmode(color);\ncolor(0.93, 0.93, 0.9);\n");
}

static void straight(double len, const char *name)
{
    begin();
    texture("road.tex.Asphalt");
    out("texmode(replace);\n");
    /* s across the road (growing to the viewer's right), t along it */
    prim("qstrip", 0);
    tex(0, 0), vert(V(ROAD_HALF, 0, 0));
    tex(2 * ROAD_HALF / TEX_TILE, 0), vert(V(-ROAD_HALF, 0, 0));
    tex(0, len / TEX_TILE), vert(V(ROAD_HALF, 0, len));
    tex(2 * ROAD_HALF / TEX_TILE, len / TEX_TILE), vert(V(-ROAD_HALF, 0, len));
    endprim();
    paint_white();
    rect_y(EDGE_IN, 0, EDGE_OUT, len, MARK_Y);
    rect_y(-EDGE_OUT, 0, -EDGE_IN, len, MARK_Y);
    for (double z = 0; z < len; z += DASH + GAP)
        rect_y(-LINE_W / 2, z, LINE_W / 2, fmin(z + DASH, len), MARK_Y);
    char what[1024];
    snprintf(what, sizeof what,
             "straight two-lane road, %g m long: asphalt 7.5 m wide, two 3.5 m lanes,\n"
             "solid 0.12 m edge lines (inner edges at x = +-3.5), broken 0.12 m centre line\n"
             "(3 m dashes every 9 m starting at z = 0, the last one cut at z = %g).\n"
             "Road surface at y = 0, markings 2 mm above it.",
             len, len);
    finish(name, what,
           "centre line at x = 0, start at z = 0; runs along +z (chain the next\n"
           "segment with trans(0, 0, length)).  Right-hand traffic heading +z uses x -3.5..0.");
}

/* A point of a left-turning curve of centreline radius R: at angle phi
 * along it, q metres to the left of the centreline.  The centre of
 * curvature is at (R, 0, 0). */
static vec curve_pt(double R, double phi, double q, double y)
{
    return V(R - (R - q) * cos(phi), y, (R - q) * sin(phi));
}

/* A strip between lateral offsets q0 < q1 from angle a0 to a1, in steps no
 * longer than dphi. */
static void curve_strip(double R, double a0, double a1, double dphi, double q0, double q1, double y, int textured)
{
    int n = (int)ceil((a1 - a0) / dphi - 1e-9);
    if (n < 1)
        n = 1;
    prim("qstrip", 0);
    for (int k = 0; k <= n; k++) {
        double phi = a0 + (a1 - a0) * k / n;
        if (textured)
            tex((ROAD_HALF - q1) / TEX_TILE, R * phi / TEX_TILE);
        vert(curve_pt(R, phi, q1, y));
        if (textured)
            tex((ROAD_HALF - q0) / TEX_TILE, R * phi / TEX_TILE);
        vert(curve_pt(R, phi, q0, y));
    }
    endprim();
}

static void curve(double R, const char *name)
{
    /* chordal deviation (sagitta) of a chord spanning dphi on the outermost
     * edge, radius R + 3.75: (R + 3.75)(1 - cos(dphi / 2)) <= 1 mm */
    double ro = R + ROAD_HALF, total = PI / 2;
    double dmax = 2 * acos(1 - 0.001 / ro);
    int n = (int)ceil(total / dmax);
    double dphi = total / n, sag = ro * (1 - cos(dphi / 2));
    begin();
    texture("road.tex.Asphalt");
    out("texmode(replace);\n");
    curve_strip(R, 0, total, dphi, -ROAD_HALF, ROAD_HALF, 0, 1);
    paint_white();
    curve_strip(R, 0, total, dphi, EDGE_IN, EDGE_OUT, MARK_Y, 0);
    curve_strip(R, 0, total, dphi, -EDGE_OUT, -EDGE_IN, MARK_Y, 0);
    double arclen = R * total;
    for (double s = 0; s < arclen; s += DASH + GAP)
        curve_strip(R, s / R, fmin(s + DASH, arclen) / R, dphi, -LINE_W / 2, LINE_W / 2, MARK_Y, 0);
    char what[1024];
    snprintf(what, sizeof what,
             "90-degree LEFT curve of a two-lane road, centreline radius %g m\n"
             "(centreline length %s m); same cross-section and markings as road.Straight*\n"
             "(dashes every 9 m of centreline arc length from the start).  Tessellated in %d\n"
             "steps of %s degrees: chordal deviation %s mm at the outer asphalt edge\n"
             "(radius %s m), less inside; dashes use the same maximum step.  Texture s across\n"
             "the road, t along the centreline arc length (2 m per repeat).",
             R, num(arclen), n, num(dphi * 180 / PI), num_d(sag * 1000, 3), num(ro));
    char origin[1024];
    snprintf(origin, sizeof origin,
             "start of the centreline at the origin, heading +z; turns towards +x\n"
             "(left) about the centre (%g, 0, 0); ends at (%g, 0, %g) heading +x.  To continue after it:\n"
             "trans(%g, 0, %g); rot(90, 0, 1, 0);.  A right curve is scale(-1, 1, 1) of this one.",
             R, R, R, R, R);
    finish(name, what, origin);
}

static void markings(void)
{
    static const double lens[] = {10, 100};
    for (int i = 0; i < 2; i++) {
        char name[128], what[512];
        double L = lens[i];
        begin();
        paint_white();
        rect_y(-LINE_W / 2, 0, LINE_W / 2, L, MARK_Y);
        snprintf(name, sizeof name, "road.markings.SolidLine%gm", L);
        snprintf(what, sizeof what, "solid longitudinal line, 0.12 m wide, %g m long, 2 mm thick.", L);
        finish(name, what, "centred on x = 0, from z = 0 along +z, bottom on y = 0 (the road surface).");

        begin();
        paint_white();
        rect_y(LINE_W / 2, 0, LINE_W * 1.5, L, MARK_Y);
        rect_y(-LINE_W * 1.5, 0, -LINE_W / 2, L, MARK_Y);
        snprintf(name, sizeof name, "road.markings.DoubleLine%gm", L);
        snprintf(what, sizeof what, "double solid line: two 0.12 m lines 0.12 m apart, %g m long.", L);
        finish(name, what, "centred on x = 0 (the gap), from z = 0 along +z, on y = 0.");
    }
    for (int periods = 1; periods <= 10; periods += 9) {
        char name[128], what[512];
        begin();
        paint_white();
        for (int k = 0; k < periods; k++)
            rect_y(-LINE_W / 2, k * (DASH + GAP), LINE_W / 2, k * (DASH + GAP) + DASH, MARK_Y);
        snprintf(name, sizeof name, "road.markings.DashedLine%gm", periods * (DASH + GAP));
        snprintf(what, sizeof what,
                 "broken line, 0.12 m wide, %d period%s of a 3 m dash and a 6 m gap\n"
                 "(%g m; the last gap is empty road).",
                 periods, periods > 1 ? "s" : "", periods * (DASH + GAP));
        finish(name, what, "centred on x = 0, first dash from z = 0 to 3, along +z, on y = 0.");
    }
    begin();
    paint_white();
    rect_y(-LANE / 2, 0, LANE / 2, 0.5, MARK_Y);
    finish("road.markings.StopLine", "stop line across one 3.5 m lane, 0.50 m deep (in z).",
           "centred on x = 0, from z = 0 to 0.5, on y = 0.  On the right-hand lane of a\n"
           "road.Straight* (traffic heading +z): trans(-1.75, 0, z).");
    begin();
    paint_white();
    for (int k = -3; k <= 3; k++)
        rect_y(k - 0.25, 0, k + 0.25, 4, MARK_Y);
    finish("road.markings.Crosswalk",
           "zebra crossing for a 7 m carriageway: 7 stripes 0.50 m wide and 4 m long,\n"
           "parallel to the road axis, 0.50 m apart (stripe centres at x = -3, -2, ..., 3).",
           "centred on x = 0, from z = 0 to 4, on y = 0.");
}

/* ---- road.signs ------------------------------------------------------------- */

/* Sign plates: the front face lies in z = 0 facing -z, the back plate (grey)
 * 2 mm behind it, a galvanised 60 mm post behind that.  Lower edge of the
 * plate 2.00 m above the ground (German VwV-StVO rule for signs over
 * footways).  Sizes: German "size 2" (VwV-StVO). */
#define PLATE_LOW 2.0
#define PLATE_T 0.002
#define POST_R 0.03

static void sign(const char *name, const char *texname, const double (*outline)[2], int n, double w, double h,
                 const char *what)
{
    begin();
    double post_z = PLATE_T + POST_R + 0.005, top = PLATE_LOW + h - 0.05;
    cylinder(V(0, 0, post_z), V(0, top, post_z), POST_R, 12, RGB(0.62, 0.63, 0.64), 1);
    /* back plate: plain grey, a separate polygon behind the face so that
     * from behind the face's texture is hidden, as on a real sign */
    out("color(0.55, 0.56, 0.57);\n");
    prim("poly", 0);
    for (int i = n - 1; i >= 0; i--)
        vert(V(outline[i][0], outline[i][1], PLATE_T));
    endprim();
    texture(texname);
    out("texmode(replace);\n");
    /* tex(0, 0) at the plate's bottom-left seen from the front: that is +x */
    prim("poly", 0);
    for (int i = 0; i < n; i++) {
        tex(0.5 - outline[i][0] / w, (outline[i][1] - PLATE_LOW) / h);
        vert(V(outline[i][0], outline[i][1], 0));
    }
    endprim();
    finish(name, what,
           "the foot of the post's front is (0, 0, 0): plate centred on x = 0, front face in\n"
           "z = 0 facing -z (towards traffic heading +z), back plate at z = 0.002, post axis at\n"
           "z = 0.037.  Place it beside the road, e.g. trans(-4.5, 0, z) for right-hand traffic.");
}

static void signs(void)
{
    double pts[64][2];
    /* stop: octagon 0.9 m across flats, flats horizontal and vertical */
    double rc = 0.45 / cos(PI / 8);
    for (int k = 0; k < 8; k++) {
        double a = (22.5 + 45 * k) * PI / 180;
        pts[k][0] = rc * cos(a), pts[k][1] = PLATE_LOW + 0.45 + rc * sin(a);
    }
    sign("road.signs.Stop", "road.signs.tex.Stop", (const double(*)[2])pts, 8, 0.9, 0.9,
         "stop sign (Vienna Convention B,2a; German StVO 206): red octagon 0.90 m\n"
         "across flats, white STOP, on a post; plate lower edge 2.00 m above the ground.");
    /* speed limit: disc 0.6 m, 48 sides: chordal deviation 0.64 mm */
    for (int k = 0; k < 48; k++) {
        double a = 2 * PI * k / 48;
        pts[k][0] = 0.3 * cos(a), pts[k][1] = PLATE_LOW + 0.3 + 0.3 * sin(a);
    }
    sign("road.signs.SpeedLimit50", "road.signs.tex.SpeedLimit50", (const double(*)[2])pts, 48, 0.6, 0.6,
         "speed limit 50 sign (Vienna C,14; StVO 274): disc 0.60 m across (48-gon,\n"
         "chordal deviation 0.64 mm), red ring, black 50, on a post; lower edge 2.00 m up.");
    /* yield: triangle, point down, 0.9 m sides */
    double th = 0.9 * sqrt(3) / 2;
    double tri[3][2] = {{0, PLATE_LOW}, {-0.45, PLATE_LOW + th}, {0.45, PLATE_LOW + th}};
    sign("road.signs.Yield", "road.signs.tex.Yield", (const double(*)[2])tri, 3, 0.9, th,
         "yield sign (Vienna B,1; StVO 205): triangle point down, 0.90 m sides, red\n"
         "border, white field, on a post; the lower point 2.00 m above the ground.");
    double sq[4][2] = {{0.3, PLATE_LOW}, {-0.3, PLATE_LOW}, {-0.3, PLATE_LOW + 0.6}, {0.3, PLATE_LOW + 0.6}};
    sign("road.signs.PedestrianCrossing", "road.signs.tex.PedestrianCrossing", (const double(*)[2])sq, 4, 0.6, 0.6,
         "pedestrian crossing sign (Vienna E,12a; StVO 350): blue square 0.60 m,\n"
         "white triangle with a walking figure, on a post; lower edge 2.00 m up.");
}

/* ---- road.vehicles ----------------------------------------------------------- */

typedef struct {
    const char *name, *what;
    double len, width;
    double body[8][2]; /* lower body profile (z, y), convex */
    int nbody;
    double cabin[4][2]; /* rear-bottom, front-bottom, front-top, rear-top */
    double cabin_w;
    rgb paint;
    double wheel_r, wheel_w, axle_f, axle_r;
} car_spec;

static const rgb GLASS = {0.12, 0.16, 0.2}, TYRE = {0.07, 0.07, 0.07}, RIM = {0.6, 0.6, 0.62};

/* A wheel at (xo = outer face x, axle z), tread and sidewall, a rim disc
 * 3 mm outside the outer face.  side = +1 on the +x side, -1 on -x. */
static void wheel(double xo, double z, double r, double w, int side)
{
    vec a = V(xo - side * w, r, z), b = V(xo, r, z);
    cylinder(a, b, r, 16, TYRE, 1);
    vec rim_c = V(xo + side * 0.003, r, z);
    prim("poly", 1);
    scol(RIM, V(side, 0, 0));
    for (int k = 0; k < 12; k++) {
        double t = 2 * PI * (side > 0 ? k : 12 - k) / 12;
        vert(add(rim_c, V(0, 0.6 * r * sin(t), 0.6 * r * cos(t))));
    }
    endprim();
}

/* A quad lying `off` outside face (a, b, c, d) of a solid, inset by `in`
 * from each edge (a-b-c-d a parallelogram): windows, lights, plates. */
static void inset_quad(vec a, vec b, vec c, vec d, double in_u, double in_v, double off, vec inside, rgb colr)
{
    vec q0[4] = {a, b, c, d};
    vec n = unit(outward(q0, 4, inside));
    vec u = unit(sub(b, a)), v = unit(sub(d, a));
    vec s = mul(n, off);
    vec q[4] = {add(add(add(a, mul(u, in_u)), mul(v, in_v)), s), add(add(sub(b, mul(u, in_u)), mul(v, in_v)), s),
                add(sub(sub(c, mul(u, in_u)), mul(v, in_v)), s), add(sub(add(d, mul(u, in_u)), mul(v, in_v)), s)};
    face(q, 4, colr, sub(inside, mul(n, 1e6)));
}

static void car(const car_spec *s)
{
    begin();
    double hw = s->width / 2, cw = s->cabin_w / 2;
    check_convex(s->body, s->nbody, s->name);
    check_convex(s->cabin, 4, s->name);
    prism_x(s->body, s->nbody, -hw, hw, s->paint);
    prism_x(s->cabin, 4, -cw, cw, s->paint);
    vec inside = V(0, (s->cabin[0][1] + s->cabin[2][1]) / 2, (s->cabin[0][0] + s->cabin[1][0]) / 2);
    /* windscreen and rear window on the sloped cabin faces */
    for (int e = 1; e <= 3; e += 2) {
        const double *p = s->cabin[e], *q = s->cabin[(e + 1) % 4];
        inset_quad(V(-cw, p[1], p[0]), V(cw, p[1], p[0]), V(cw, q[1], q[0]), V(-cw, q[1], q[0]), 0.08, 0.05, 0.004,
                   inside, GLASS);
    }
    /* side windows: the cabin side inset by 6 cm, split by a B pillar */
    double in = 0.06, win[4][2];
    for (int i = 0; i < 4; i++) { /* offset each edge inwards, intersect neighbours */
        const double *a = s->cabin[(i + 3) % 4], *b = s->cabin[i], *c = s->cabin[(i + 1) % 4];
        double d1z = b[0] - a[0], d1y = b[1] - a[1], d2z = c[0] - b[0], d2y = c[1] - b[1];
        double l1 = hypot(d1z, d1y), l2 = hypot(d2z, d2y);
        /* profile is counter-clockwise in (z, y) seen from +x: inward normal is the left normal */
        double n1z = -d1y / l1, n1y = d1z / l1, n2z = -d2y / l2, n2y = d2z / l2;
        double az = a[0] + n1z * in, ay = a[1] + n1y * in, bz = b[0] + n2z * in, by = b[1] + n2y * in;
        double det = d1z * (-d2y) - d1y * (-d2z);
        double t = ((bz - az) * (-d2y) - (by - ay) * (-d2z)) / det;
        win[i][0] = az + d1z * t, win[i][1] = ay + d1y * t;
    }
    double pz = (win[0][0] + win[1][0]) / 2 - 0.1;
    for (int side = -1; side <= 1; side += 2) {
        double x = side * (cw + 0.004);
        vec w[4];
        for (int i = 0; i < 4; i++)
            w[i] = V(x, win[i][1], win[i][0]);
        face(w, 4, GLASS, V(0, w[0].y, w[0].z));
        double top = win[3][1] + (win[2][1] - win[3][1]) * (pz - win[3][0]) / (win[2][0] - win[3][0]);
        vec pil[4] = {V(side * (cw + 0.007), win[0][1] - 0.01, pz - 0.05),
                      V(side * (cw + 0.007), win[0][1] - 0.01, pz + 0.05),
                      V(side * (cw + 0.007), top + 0.01, pz + 0.05), V(side * (cw + 0.007), top + 0.01, pz - 0.05)};
        face(pil, 4, s->paint, V(0, pil[0].y, pz));
    }
    /* lights and plates on the vertical front and rear ends of the body */
    double zf = -1e9, zr = 1e9, yf0 = 1e9, yf1 = -1e9, yr0 = 1e9, yr1 = -1e9;
    for (int i = 0; i < s->nbody; i++)
        zf = fmax(zf, s->body[i][0]), zr = fmin(zr, s->body[i][0]);
    for (int i = 0; i < s->nbody; i++) {
        if (s->body[i][0] == zf)
            yf0 = fmin(yf0, s->body[i][1]), yf1 = fmax(yf1, s->body[i][1]);
        if (s->body[i][0] == zr)
            yr0 = fmin(yr0, s->body[i][1]), yr1 = fmax(yr1, s->body[i][1]);
    }
    vec bin = V(0, (yf0 + yf1) / 2, 0);
    for (int side = -1; side <= 1; side += 2) {
        double x0 = side * (hw - 0.08), x1 = side * (hw - 0.38);
        inset_quad(V(x0, yf1 - 0.16, zf), V(x1, yf1 - 0.16, zf), V(x1, yf1 - 0.04, zf), V(x0, yf1 - 0.04, zf), 0, 0,
                   0.004, bin, RGB(0.95, 0.93, 0.8));
        inset_quad(V(x0, yr1 - 0.18, zr), V(x1, yr1 - 0.18, zr), V(x1, yr1 - 0.04, zr), V(x0, yr1 - 0.04, zr), 0, 0,
                   0.004, bin, RGB(0.75, 0.05, 0.05));
    }
    /* EU plates 520 x 110 mm */
    inset_quad(V(-0.26, yf0 + 0.08, zf), V(0.26, yf0 + 0.08, zf), V(0.26, yf0 + 0.19, zf), V(-0.26, yf0 + 0.19, zf), 0,
               0, 0.004, bin, RGB(0.93, 0.93, 0.9));
    inset_quad(V(-0.26, yr0 + 0.1, zr), V(0.26, yr0 + 0.1, zr), V(0.26, yr0 + 0.21, zr), V(-0.26, yr0 + 0.21, zr), 0,
               0, 0.004, bin, RGB(0.93, 0.93, 0.9));
    for (int side = -1; side <= 1; side += 2) {
        wheel(side * (hw + 0.01), s->axle_f, s->wheel_r, s->wheel_w, side);
        wheel(side * (hw + 0.01), s->axle_r, s->wheel_r, s->wheel_w, side);
    }
    finish(s->name, s->what,
           "centre of the footprint on the ground (x = 0, y = 0, z = 0, midway between\n"
           "the bumpers); nose towards +z (drives along +z), so a camera behind it (at -z)\n"
           "sees its rear; +x is its left side.  Wheels touch y = 0; tyres are 16-gon prisms.");
}

static void truck(void)
{
    begin();
    rgb cabc = RGB(0.85, 0.75, 0.15), boxc = RGB(0.88, 0.88, 0.86), dark = RGB(0.18, 0.18, 0.2);
    double hw = 1.25;
    /* cab above the front wheels: front at z = 4, 2.1 m long, raked windscreen */
    double cab[5][2] = {{1.9, 1.05}, {4.0, 1.05}, {4.0, 2.0}, {3.85, 3.1}, {1.9, 3.1}};
    check_convex(cab, 5, "truck cab");
    prism_x(cab, 5, -hw, hw, cabc);
    box(V(-hw, 1.05, -4.0), V(hw, 3.6, 1.8), boxc);              /* cargo box */
    box(V(-0.45, 0.55, -4.0), V(0.45, 1.05, 3.9), dark);         /* chassis frame */
    box(V(-hw + 0.05, 0.45, 3.9), V(hw - 0.05, 0.85, 4.1), dark); /* bumper */
    vec cin = V(0, 2.0, 3.0);
    inset_quad(V(-hw, 2.0, 4.0), V(hw, 2.0, 4.0), V(hw, 3.1, 3.85), V(-hw, 3.1, 3.85), 0.1, 0.08, 0.004, cin, GLASS);
    for (int side = -1; side <= 1; side += 2) {
        double x = side * (hw + 0.004);
        vec w[4] = {V(x, 2.05, 2.9), V(x, 2.05, 3.75), V(x, 2.95, 3.75), V(x, 2.95, 2.9)};
        face(w, 4, GLASS, V(0, 2.5, 3.3));
        vec hl[4] = {V(side * 0.95, 1.15, 4.004), V(side * 0.65, 1.15, 4.004), V(side * 0.65, 1.3, 4.004),
                     V(side * 0.95, 1.3, 4.004)};
        face(hl, 4, RGB(0.95, 0.93, 0.8), V(0, 1.2, 3.0));
        vec tl[4] = {V(side * 1.15, 1.15, -4.004), V(side * 0.85, 1.15, -4.004), V(side * 0.85, 1.35, -4.004),
                     V(side * 1.15, 1.35, -4.004)};
        face(tl, 4, RGB(0.75, 0.05, 0.05), V(0, 1.2, 0));
        wheel(side * (hw - 0.02), 2.9, 0.5, 0.3, side);
        wheel(side * (hw - 0.02), -2.3, 0.5, 0.55, side); /* twin tyres */
    }
    inset_quad(V(-0.26, 0.55, 4.1), V(0.26, 0.55, 4.1), V(0.26, 0.66, 4.1), V(-0.26, 0.66, 4.1), 0, 0, 0.004,
               V(0, 0.5, 0), RGB(0.93, 0.93, 0.9));
    inset_quad(V(-0.26, 1.15, -4.0), V(0.26, 1.15, -4.0), V(0.26, 1.26, -4.0), V(-0.26, 1.26, -4.0), 0, 0, 0.004,
               V(0, 1.0, 0), RGB(0.93, 0.93, 0.9));
    finish("road.vehicles.Truck",
           "box truck (7.5 t class): yellow cab with windscreen and side windows, white\n"
           "cargo box 5.8 m long, dark chassis and bumper, single front and twin rear tyres\n"
           "(radius 0.5 m), lights, plates.",
           "centre of the footprint on the ground (x = 0, y = 0, z = 0); nose towards +z;\n"
           "+x is its left side.  Wheels touch y = 0.");
}

static void vehicles(void)
{
    static const car_spec cars[] = {
        {"road.vehicles.Sedan",
         "saloon car, red: lower body, cabin with windscreen, rear and side windows,\n"
         "B pillars, head and tail lights, EU plates, four wheels (radius 0.32 m).",
         4.6, 1.8,
         {{-2.3, 0.28}, {2.3, 0.28}, {2.3, 0.72}, {1.9, 0.86}, {0.95, 0.92}, {-2.15, 0.98}, {-2.3, 0.9}},
         7,
         {{-1.75, 0.92}, {0.95, 0.92}, {0.05, 1.42}, {-1.15, 1.42}},
         1.6,
         {0.72, 0.08, 0.08},
         0.32, 0.21, 1.4, -1.3},
        {"road.vehicles.Hatchback",
         "hatchback car, blue: short bonnet, steep tailgate, windows, lights, plates,\n"
         "four wheels (radius 0.31 m).",
         4.0, 1.75,
         {{-2.0, 0.28}, {2.0, 0.28}, {2.0, 0.7}, {1.7, 0.86}, {1.05, 0.92}, {-2.0, 0.96}},
         6,
         {{-1.95, 0.94}, {1.05, 0.92}, {0.2, 1.48}, {-1.75, 1.5}},
         1.58,
         {0.12, 0.25, 0.62},
         0.31, 0.2, 1.3, -1.25},
        {"road.vehicles.Van",
         "passenger van (minibus), white: tall boxy body, steep windscreen, windows\n"
         "all along, lights, plates, four wheels (radius 0.34 m).",
         5.0, 2.0,
         {{-2.5, 0.3}, {2.5, 0.3}, {2.5, 0.85}, {2.2, 1.05}, {-2.5, 1.05}},
         5,
         {{-2.5, 1.05}, {2.2, 1.05}, {1.6, 2.0}, {-2.45, 2.0}},
         1.96,
         {0.9, 0.9, 0.88},
         0.34, 0.22, 1.75, -1.65},
    };
    for (size_t i = 0; i < sizeof cars / sizeof cars[0]; i++)
        car(&cars[i]);
    truck();
}

/* ---- calib ------------------------------------------------------------------ */

/* Calibration targets are built from geometry so that corners and centres
 * are exact, not texture-filtered.  The black features lie exactly in the
 * plane z = 0; the white backing is 0.1 mm BEHIND them (z = +0.0001, away
 * from the viewer): the player's depth test is GL_GREATER with reversed Z,
 * so a coplanar surface drawn later would lose or flicker, while 0.1 mm is
 * far above float depth resolution at calibration distances and far below
 * anything a camera resolves.  Markers on black squares are 0.1 mm in front
 * (z = -0.0001).  Front faces -z.  Seen from the front, +x points to the
 * viewer's LEFT and +y up: this (x, y, z) frame is right-handed with z
 * pointing into the board, away from the viewer, as in OpenCV's object
 * frame (it is OpenCV's "x right, y down" frame turned 180 degrees about
 * z). */
#define BLACKC "color(0.05, 0.05, 0.05);\n"
#define WHITEC "color(0.95, 0.95, 0.95);\n"
#define BACK_Z 0.0001

static void backing(double x0, double y0, double x1, double y1)
{
    out(WHITEC);
    rect_z(x0, y0, x1, y1, BACK_Z);
    out(BLACKC);
}

static void disc(double cx, double cy, double r, double z, int n)
{
    prim("poly", 0);
    for (int k = 0; k < n; k++) {
        double a = 2 * PI * k / n;
        vert(V(cx + r * cos(a), cy + r * sin(a), z));
    }
    endprim();
}

static void checker(int cols, int rows, double s, int marker)
{
    char name[128], what[2048];
    begin();
    /* squares (a, b), a = -1..cols-1, b = -1..rows-1, span [a s, (a+1) s] x
       [b s, (b+1) s]; black where a + b is even; a white margin one square
       wide around them */
    backing(-2 * s, -2 * s, (cols + 1) * s, (rows + 1) * s);
    for (int b = -1; b < rows; b++)
        for (int a = -1; a < cols; a++)
            if (((a + b) % 2 + 2) % 2 == 0)
                rect_z(a * s, b * s, (a + 1) * s, (b + 1) * s, 0);
    int mc = cols / 2 - 1 + (cols / 2 - 1) % 2, mr = rows / 2 - 1; /* a black square near the middle */
    if ((mc + mr) % 2)
        mr++;
    if (marker) {
        out(WHITEC);
        disc((mc + 0.5) * s, (mr + 0.5) * s, 0.3 * s, -BACK_Z, 48);
        out(BLACKC);
        disc((mc + 1.5) * s, (mr + 0.5) * s, 0.3 * s, -BACK_Z, 48);
    }
    snprintf(name, sizeof name, "calib.%sChecker%dx%d_%gmm", marker ? "Marker" : "", cols, rows, s * 1000);
    int n = snprintf(what, sizeof what,
                     "checkerboard with %d x %d inner corners (%d x %d squares of %g mm) on a\n"
                     "white backing with a one-square white margin (board %s x %s m).  Inner corner\n"
                     "(i, j), i = 0..%d, j = 0..%d, is at (i*s, j*s, 0) with s = %s: corners are exact\n"
                     "geometry.  Square (a, b) = [a s, (a+1) s] x [b s, (b+1) s], a = -1..%d, b = -1..%d,\n"
                     "is black when a + b is even (so square (0, 0) is black).  %s\n"
                     "Black squares in z = 0, backing 0.1 mm behind (z = +0.0001).",
                     cols, rows, cols + 1, rows + 1, s * 1000, num((cols + 3) * s), num((rows + 3) * s), cols - 1,
                     rows - 1, num(s), cols - 1, rows - 1,
                     (cols + rows) % 2 ? "Square counts even x odd:\n"
                                         "no 180-degree symmetry, so its orientation is unambiguous."
                                       : "Square counts both even or\n"
                                         "both odd: symmetric under a 180-degree turn (use the Marker board to disambiguate).");
    if (marker)
        snprintf(what + n, sizeof what - (size_t)n,
                 "\nMarkers (unique orientation and origin): a white disc of diameter 0.6 s\n"
                 "centred at (%s, %s) in black square (%d, %d), and a black disc of diameter\n"
                 "0.6 s centred at (%s, %s) in the white square (%d, %d) beside it; both 0.1 mm\n"
                 "in front (z = -0.0001), 48-gons.",
                 num((mc + 0.5) * s), num((mr + 0.5) * s), mc, mr, num((mc + 1.5) * s), num((mr + 0.5) * s), mc + 1,
                 mr);
    finish(name, what,
           "inner corner (0, 0); the board lies in z = 0 and faces -z; seen from the\n"
           "front, i (x) runs to the viewer's LEFT and j (y) up, z points into the board.");
}

static void circle_grid(int cols, int rows, double a, double diam, int asym)
{
    char name[128], what[2048];
    begin();
    double w = asym ? (2 * (cols - 1) + 1) * a : (cols - 1) * a, h = (rows - 1) * a, m = a + diam / 2;
    backing(-m, -m, w + m, h + m);
    for (int j = 0; j < rows; j++)
        for (int i = 0; i < cols; i++)
            disc(asym ? (2 * i + j % 2) * a : i * a, j * a, diam / 2, 0, 64);
    snprintf(name, sizeof name, "calib.CircleGrid%dx%d", cols, rows);
    if (asym)
        snprintf(what, sizeof what,
                 "ASYMMETRIC circle grid, %d x %d (OpenCV CALIB_CB_ASYMMETRIC_GRID, pattern size\n"
                 "(%d, %d)): black discs of diameter %g mm on white.  Centre (i, j), i = 0..%d,\n"
                 "j = 0..%d, at ((2 i + j mod 2) a, j a, 0) with a = %s m (so %g mm between\n"
                 "neighbours in a row, %s mm diagonally).  Discs are 64-gons (chordal deviation\n"
                 "%s mm; a regular polygon's centroid is its centre).  Backing margin: a plus\n"
                 "the radius beyond the outermost centres; 0.1 mm behind the discs.",
                 cols, rows, cols, rows, diam * 1000, cols - 1, rows - 1, num(a), 2 * a * 1000,
                 num_d(sqrt(2) * a * 1000, 3), num_d(diam / 2 * (1 - cos(PI / 64)) * 1000, 4));
    else
        snprintf(what, sizeof what,
                 "SYMMETRIC circle grid, %d x %d (OpenCV CALIB_CB_SYMMETRIC_GRID, pattern size\n"
                 "(%d, %d)): black discs of diameter %g mm on white.  Centre (i, j), i = 0..%d,\n"
                 "j = 0..%d, at (i a, j a, 0) with a = %s m.  Discs are 64-gons (chordal deviation\n"
                 "%s mm; a regular polygon's centroid is its centre).  Backing margin: a plus\n"
                 "the radius beyond the outermost centres; 0.1 mm behind the discs.",
                 cols, rows, cols, rows, diam * 1000, cols - 1, rows - 1, num(a),
                 num_d(diam / 2 * (1 - cos(PI / 64)) * 1000, 4));
    finish(name, what,
           "centre (0, 0); the grid lies in z = 0 and faces -z; seen from the front, i (x)\n"
           "runs to the viewer's LEFT and j (y) up, z points into the board.");
}

static void calib(void)
{
    checker(9, 6, 0.025, 0);
    checker(7, 6, 0.04, 0);
    checker(11, 8, 0.1, 0);
    checker(9, 6, 0.025, 1);
    circle_grid(4, 11, 0.02, 0.016, 1);
    circle_grid(7, 6, 0.03, 0.015, 0);
}

/* ---- stereo ------------------------------------------------------------------- */

/* Random-dot surfaces for dense stereo: stereo.tex.RandomDots has one dot
 * per texel and is mapped at 1 cm per texel (2.56 m per repeat). */
#define DOT_TILE 2.56

static void stereo_planes(void)
{
    begin();
    texture("stereo.tex.RandomDots");
    out("texmode(replace);\n");
    prim("poly", 0);
    tex(0, 0), vert(V(2, -1.5, 0));
    tex(4 / DOT_TILE, 0), vert(V(-2, -1.5, 0));
    tex(4 / DOT_TILE, 3 / DOT_TILE), vert(V(-2, 1.5, 0));
    tex(0, 3 / DOT_TILE), vert(V(2, 1.5, 0));
    endprim();
    finish("stereo.RandomDotPlane",
           "fronto-parallel plane 4 m x 3 m covered with random dots (1 cm dots, binary\n"
           "black/white, stereo.tex.RandomDots at 1 cm per texel).",
           "centre of the plane; it lies in z = 0 and faces -z.");

    begin();
    texture("stereo.tex.Noise");
    out("texmode(replace);\n");
    prim("poly", 0);
    tex(0, 0), vert(V(2, -1.5, 0));
    tex(2, 0), vert(V(-2, -1.5, 0));
    tex(2, 1.5), vert(V(-2, 1.5, 0));
    tex(0, 1.5), vert(V(2, 1.5, 0));
    endprim();
    finish("stereo.NoisePlane",
           "fronto-parallel plane 4 m x 3 m with multi-scale grey noise\n"
           "(stereo.tex.Noise, 2 m per repeat): texture at every pyramid level.",
           "centre of the plane; it lies in z = 0 and faces -z.");

    /* the random-dot plane turned 45 degrees about the vertical axis: x' = x
     * cos 45, z' = -x sin 45, so the viewer's left edge (+x) comes nearer */
    double c = sqrt(0.5);
    begin();
    texture("stereo.tex.RandomDots");
    out("texmode(replace);\n");
    prim("poly", 0);
    tex(0, 0), vert(V(2 * c, -1.5, -2 * c));
    tex(4 / DOT_TILE, 0), vert(V(-2 * c, -1.5, 2 * c));
    tex(4 / DOT_TILE, 3 / DOT_TILE), vert(V(-2 * c, 1.5, 2 * c));
    tex(0, 3 / DOT_TILE), vert(V(2 * c, 1.5, -2 * c));
    endprim();
    finish("stereo.SlantedPlane",
           "the 4 m x 3 m random-dot plane slanted by 45 degrees about the vertical\n"
           "axis: depth changes along the image rows (the hard case for window-based\n"
           "matchers).  Plane: z = -x (normal (1, 0, 1)/sqrt 2); the edge on the\n"
           "viewer's left (+x) is nearer.",
           "centre of the plane, on its vertical axis of rotation; faces -z (and +x).");
}

static void staircase(void)
{
    const int n = 8;
    const double rise = 0.17, go = 0.29, hw = 1.0;
    rgb grey = RGB(1, 1, 1);
    begin();
    texture("stereo.tex.RandomDots");
    out("texmode(modulate);\n");
    /* dots modulated by face shading, so the step edges also show in
     * intensity; s, t at 1 cm per texel */
    vec in = V(0, 0.5, 1);
    for (int k = 0; k < n; k++) {
        double z0 = k * go, z1 = (k + 1) * go, y0 = k * rise, y1 = (k + 1) * rise;
        vec r[4] = {V(hw, y0, z0), V(-hw, y0, z0), V(-hw, y1, z0), V(hw, y1, z0)};
        prim("poly", 1);
        scol(grey, V(0, 0, -1));
        for (int i = 0; i < 4; i++)
            tex((hw - r[i].x) / DOT_TILE, r[i].y / DOT_TILE), vert(r[i]);
        endprim();
        vec t[4] = {V(hw, y1, z0), V(-hw, y1, z0), V(-hw, y1, z1), V(hw, y1, z1)};
        prim("poly", 1);
        scol(grey, V(0, 1, 0));
        for (int i = 0; i < 4; i++)
            tex((hw - t[i].x) / DOT_TILE, (t[i].z + 1.3) / DOT_TILE), vert(t[i]);
        endprim();
        for (int side = -1; side <= 1; side += 2) {
            vec sd[4] = {V(side * hw, 0, z0), V(side * hw, 0, z1), V(side * hw, y1, z1), V(side * hw, y1, z0)};
            prim("poly", 1);
            scol(grey, V(side, 0, 0));
            for (int i = 0; i < 4; i++)
                tex(sd[i].z / DOT_TILE, sd[i].y / DOT_TILE), vert(sd[i]);
            endprim();
        }
    }
    vec back[4] = {V(hw, 0, n * go), V(hw, n * rise, n * go), V(-hw, n * rise, n * go), V(-hw, 0, n * go)};
    face(back, 4, RGB(0.5, 0.5, 0.5), in);
    finish("stereo.Staircase",
           "staircase of 8 steps, rise 0.17 m, going 0.29 m (DIN 18065 comfort rule\n"
           "2 r + g = 0.63 m), 2 m wide, closed sides and back; risers, treads and sides\n"
           "carry random dots modulated by per-face shading.  Top tread at y = 1.36.",
           "foot of the first riser, centred: the first riser lies in z = 0 facing -z,\n"
           "the stairs climb towards +z (up, away from a camera at -z), x from -1 to 1.");
}

static void sphere(const char *name, double r, vec c, int nlon, int nlat, const char *texname, double tile, rgb base,
                   const char *what, const char *origin)
{
    /* a whole number of texture repeats around: no seam in the pattern */
    double reps = texname ? round(2 * PI * r / tile) : 1;
    begin();
    if (texname) {
        texture(texname);
        out("texmode(modulate);\n");
    }
    for (int j = 0; j < nlat; j++) {
        prim("qstrip", 0);
        for (int i = 0; i <= nlon; i++) {
            for (int e = 1; e >= 0; e--) {
                double lat = -PI / 2 + PI * (j + e) / nlat, lon = 2 * PI * (i % nlon) / nlon;
                /* longitude 0 at the back (+z): the texture seam faces away */
                vec d = V(cos(lat) * sin(lon), sin(lat), cos(lat) * cos(lon));
                scol(base, d);
                if (texname)
                    tex(reps * i / nlon, r * (lat + PI / 2) / tile);
                vert(add(c, mul(d, r)));
            }
        }
        endprim();
    }
    finish(name, what, origin);
}

static void eggcrate(void)
{
    const double A = 0.08, lambda = 1.0, W = 3.0, H = 2.0, step = 0.05;
    int nx = (int)lrint(W / step), ny = (int)lrint(H / step);
    begin();
    texture("stereo.tex.RandomDots");
    out("texmode(modulate);\n");
    for (int j = 0; j < ny; j++) {
        prim("qstrip", 0);
        for (int i = 0; i <= nx; i++) {
            for (int e = 1; e >= 0; e--) {
                double x = W / 2 - i * step, y = -H / 2 + (j + e) * step;
                double kx = 2 * PI / lambda;
                double z = A * sin(kx * x) * sin(kx * y);
                /* normal of z = f(x, y) facing -z: (f_x, f_y, -1) */
                vec n = V(A * kx * cos(kx * x) * sin(kx * y), A * kx * sin(kx * x) * cos(kx * y), -1);
                scol(RGB(1, 1, 1), n);
                tex((W / 2 - x) / DOT_TILE, (y + H / 2) / DOT_TILE);
                vert(V(x, y, z));
            }
        }
        endprim();
    }
    finish("stereo.EggCrate",
           "egg-crate surface 3 m x 2 m, z = 0.08 sin(2 pi x) sin(2 pi y) (wavelength 1 m,\n"
           "amplitude 8 cm), random dots modulated by shading.  5 cm grid: chordal\n"
           "deviation below 1 mm (smallest radius of curvature 1/(0.08 (2 pi)^2) = 0.317 m,\n"
           "sagitta of a 7.1 cm diagonal 0.2 mm).",
           "centre of the surface (on its mean plane z = 0); faces -z.");
}

static void stereo(void)
{
    stereo_planes();
    staircase();
    /* 72 x 36: a step of 5 degrees; chordal deviation r (1 - cos 2.5 deg) = 0.95 mm for r = 1 m */
    sphere("stereo.Sphere", 1.0, V(0, 0, 0), 72, 36, "stereo.tex.RandomDots", DOT_TILE, RGB(1, 1, 1),
           "sphere of radius 1 m, 72 x 36 facets (5-degree steps: chordal deviation\n"
           "0.95 mm), random dots modulated by smooth shading (2 repeats around the\n"
           "equator, dots about 1.2 cm; texture seam at the back, +z).",
           "centre of the sphere.");
    eggcrate();
}

/* ---- objects ------------------------------------------------------------------- */

static void solids(void)
{
    static const struct {
        const char *suffix, *colname;
        rgb c;
    } boxes[] = {
        {"", "grey", {0.7, 0.7, 0.7}},     {"Red", "red", {0.85, 0.15, 0.12}},
        {"Green", "green", {0.15, 0.65, 0.2}}, {"Blue", "blue", {0.15, 0.3, 0.85}},
        {"Yellow", "yellow", {0.92, 0.8, 0.1}},
    };
    const char *origin = "centre of the bottom face, standing on y = 0; faces are axis-aligned.";
    for (size_t i = 0; i < sizeof boxes / sizeof boxes[0]; i++) {
        char name[64], what[256];
        begin();
        box(V(-0.5, 0, -0.5), V(0.5, 1, 0.5), boxes[i].c);
        snprintf(name, sizeof name, "objects.Box%s", boxes[i].suffix);
        snprintf(what, sizeof what, "unit cube (1 m), %s, each face flat-shaded differently.", boxes[i].colname);
        finish(name, what, origin);
    }

    /* textured box: each face shows a different part of the speckle texture,
     * so that faces can be told apart by a tracker */
    begin();
    texture("objects.tex.Speckle");
    out("texmode(modulate);\n");
    vec a = V(-0.5, 0, -0.5), b = V(0.5, 1, 0.5), in = V(0, 0.5, 0);
    vec f[6][4] = {
        {V(b.x, a.y, a.z), V(a.x, a.y, a.z), V(a.x, b.y, a.z), V(b.x, b.y, a.z)}, /* front, -z */
        {V(a.x, a.y, b.z), V(b.x, a.y, b.z), V(b.x, b.y, b.z), V(a.x, b.y, b.z)}, /* back */
        {V(a.x, a.y, a.z), V(a.x, a.y, b.z), V(a.x, b.y, b.z), V(a.x, b.y, a.z)}, /* -x */
        {V(b.x, a.y, b.z), V(b.x, a.y, a.z), V(b.x, b.y, a.z), V(b.x, b.y, b.z)}, /* +x */
        {V(b.x, b.y, a.z), V(a.x, b.y, a.z), V(a.x, b.y, b.z), V(b.x, b.y, b.z)}, /* top */
        {V(b.x, a.y, b.z), V(a.x, a.y, b.z), V(a.x, a.y, a.z), V(b.x, a.y, a.z)}, /* bottom */
    };
    for (int k = 0; k < 6; k++) {
        double s0 = 0.5 * (k % 2), t0 = (k / 2) / 3.0;
        double st[4][2] = {{s0, t0}, {s0 + 0.5, t0}, {s0 + 0.5, t0 + 1 / 3.0}, {s0, t0 + 1 / 3.0}};
        prim("poly", 1);
        scol(RGB(1, 1, 1), outward(f[k], 4, in));
        for (int i = 0; i < 4; i++)
            tex(st[i][0], st[i][1]), vert(f[k][i]);
        endprim();
    }
    finish("objects.TexturedBox",
           "unit cube (1 m) textured with coloured speckles, modulated by face shading;\n"
           "each face shows a different sixth of objects.tex.Speckle (s 0..0.5 or 0.5..1,\n"
           "t in thirds), upright as seen from outside, so faces can be told apart.",
           origin);

    begin();
    /* 64 sides: chordal deviation 0.5 (1 - cos(pi/64)) = 0.6 mm */
    cylinder(V(0, 0, 0), V(0, 1, 0), 0.5, 64, RGB(0.2, 0.6, 0.75), 1);
    finish("objects.Cylinder",
           "cylinder of radius 0.5 m and height 1 m, axis vertical, 64 sides (chordal\n"
           "deviation 0.6 mm), side smooth-shaded, caps flat.",
           "centre of the bottom cap, standing on y = 0.");

    begin();
    {
        rgb c = RGB(0.85, 0.45, 0.1);
        prim("tfan", 0);
        int n = 64;
        double slope = 0.5; /* r / h */
        scol(c, V(0, 1, 0));
        vert(V(0, 1, 0));
        for (int k = 0; k <= n; k++) {
            double t = 2 * PI * (k % n) / n;
            scol(c, V(sin(t), slope, -cos(t)));
            vert(V(0.5 * sin(t), 0, -0.5 * cos(t)));
        }
        endprim();
        prim("poly", 0);
        scol(c, V(0, -1, 0));
        for (int k = 0; k < n; k++) {
            double t = -2 * PI * k / n;
            vert(V(0.5 * sin(t), 0, -0.5 * cos(t)));
        }
        endprim();
    }
    finish("objects.Cone",
           "cone of base radius 0.5 m and height 1 m, axis vertical, 64 sides (chordal\n"
           "deviation 0.6 mm), smooth-shaded side, flat base.",
           "centre of the base, standing on y = 0; apex at (0, 1, 0).");

    begin();
    {
        rgb c = RGB(0.75, 0.3, 0.65);
        vec apex = V(0, 1, 0), base[4] = {V(0.5, 0, -0.5), V(-0.5, 0, -0.5), V(-0.5, 0, 0.5), V(0.5, 0, 0.5)};
        vec in2 = V(0, 0.25, 0);
        for (int k = 0; k < 4; k++) {
            vec t[3] = {base[k], base[(k + 1) % 4], apex};
            face(t, 3, c, in2);
        }
        face(base, 4, c, in2);
    }
    finish("objects.Pyramid", "square pyramid, base 1 m x 1 m, height 1 m, each face flat-shaded.",
           "centre of the base, standing on y = 0; apex at (0, 1, 0).");

    /* 64 x 32: 5.625-degree steps, chordal deviation 0.5 (1 - cos(2.8125 deg)) = 0.6 mm */
    sphere("objects.Sphere", 0.5, V(0, 0.5, 0), 64, 32, NULL, 1, RGB(0.3, 0.7, 0.3),
           "sphere of diameter 1 m, 64 x 32 facets (chordal deviation 0.6 mm),\n"
           "green, smooth-shaded.",
           "bottom point of the sphere, standing on y = 0; centre at (0, 0.5, 0).");
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gen_objects OUTROOT\n");
        return 2;
    }
    outroot = argv[1];
    if (gls_mkdir_p(outroot)) {
        fprintf(stderr, "gen_objects: cannot create %s: %s\n", outroot, strerror(errno));
        return 1;
    }
    straight(10, "road.Straight10m");
    straight(50, "road.Straight50m");
    straight(100, "road.Straight100m");
    curve(50, "road.Curve50m");
    curve(200, "road.Curve200m");
    curve(400, "road.Curve400m");
    markings();
    signs();
    vehicles();
    calib();
    stereo();
    solids();
    return 0;
}
