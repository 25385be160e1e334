/* The ids of the instance and class outputs (runtime/truth/gt_table.h): ranks
 * among the drawing instances in call-path order, call paths with #k per
 * parent and object, classes from packages, sorted. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "gt_table.h"
#include "player_scene.h"

static void tri(tb *t)
{
    static const double q[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tb_poly(t, 3, q);
}

static void test_class_of(void)
{
    char c[64];
    gls_gt_package_of("road.vegetation.Birch", c, sizeof c);
    CHECK(strcmp(c, "road.vegetation") == 0);
    gls_gt_package_of("Wall", c, sizeof c);
    CHECK(strcmp(c, "Wall") == 0);
    gls_gt_package_of("a.B", c, 2); /* cut to the buffer */
    CHECK(strcmp(c, "a") == 0);
    /* a specialised object: its values' dots are not package dots */
    gls_gt_package_of("road.signs.Sign(h=1.5,w=0.75)", c, sizeof c);
    CHECK(strcmp(c, "road.signs") == 0);
    gls_gt_package_of("Sign(h=1.5)", c, sizeof c);
    CHECK(strcmp(c, "Sign") == 0);
}

/* Top calls a.B twice, then c.d.Leaf, then Solo; a.B draws nothing and
 * calls c.d.Leaf twice. */
static void test_paths(void)
{
    tb t;
    tb_init(&t);
    uint32_t solo = tb_object(&t, "Solo", 0);
    tri(&t);
    uint32_t top = tb_object(&t, "Top", 1);
    uint32_t ab = tb_object(&t, "a.B", 0);
    uint32_t leaf = tb_object(&t, "c.d.Leaf", 0);
    tri(&t);
    t.cur = ab;
    for (int k = 0; k < 2; k++) {
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, k, 0, 0);
        tb_call(&t, leaf);
        tb_op0(&t, GLS_OP_POP);
    }
    t.cur = top;
    for (int k = 0; k < 2; k++) {
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, 0, k, 0);
        tb_call(&t, ab);
        tb_op0(&t, GLS_OP_POP);
    }
    tb_call(&t, leaf);
    tb_call(&t, solo);
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    gls_gt_table g;
    uint32_t count = 0;
    CHECK(gls_gt_table_build(&g, b, &s, &count) == 0);
    CHECK(count == 6 && g.nids == 6 && g.ninst == s.ninst && s.ninst == 9);
    static const char *const paths[6] = {"Top > a.B#1 > c.d.Leaf#1", "Top > a.B#1 > c.d.Leaf#2",
                                         "Top > a.B#2 > c.d.Leaf#1", "Top > a.B#2 > c.d.Leaf#2",
                                         "Top > c.d.Leaf#1",         "Top > Solo#1"};
    for (uint32_t i = 0; i < 6 && g.nids == 6; i++) {
        CHECK_MSG(strcmp(g.path[i], paths[i]) == 0, "id %u: %s", i + 1, g.path[i]);
        CHECK(g.name[i] == NULL);
        CHECK(g.class_id[i] == (i == 5 ? 1 : 2));
    }
    CHECK(g.nclasses == 2 && strcmp(g.classes[0], "Solo") == 0 && strcmp(g.classes[1], "c.d") == 0);
    /* ids per scene instance: those that draw, in order; the rest 0 */
    uint32_t drawn = 0;
    for (uint32_t i = 0; i < s.ninst; i++) {
        CHECK((g.id[i] != 0) == (s.inst[i].nitems > 0));
        if (g.id[i])
            CHECK(g.id[i] == ++drawn);
    }
    gls_gt_table_free(&g);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

int main(void)
{
    RUN(test_class_of);
    RUN(test_paths);
    CHECK_EXIT();
}
