/* ffl-test: differential */
/*
 * examples/legacy/torus_envmap.c, a classic environment-mapping program (a lit torus with
 * GL_SPHERE_MAP texture coordinate generation) written against the system <GL/gl.h>
 * only: its init(), reshape() and display() built unchanged against fflight and against
 * OSMesa, display() run in feedback mode. Positions, colors and texture coordinates are
 * compared across the builds, and each vertex's texture coordinates in both builds
 * against reference/texgen_ref.h's double-precision evaluation of §2.11.4 (sphere map s
 * and t, the current r = 0 and q = 1, then unit 0's texture matrix) within 1e-5. (OSMesa
 * generates them here because the unit has a complete texture enabled; without one its
 * feedback returns the current coordinates: docs/osmesa-differences.md, 19.)
 */
#include <GL/gl.h>
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"
#include "reference/texgen_ref.h"
#include "reference/legacy_ref.h"

#define glBegin lref_begin
#define glNormal3f lref_normal3f
#define glVertex3f lref_vertex3f
#define main torus_envmap_main
#include "../examples/legacy/torus_envmap.c"
#undef main

/* Sphere map s and t (§2.11.4), the current r = 0 and q = 1, the texture matrix. */
static void sphere_map(const double *object, double *strq)
{
    tref_vertex v;
    double generated[4];
    tref_vertex_terms(lref.ref.modelview.m, object, lref.normal, &v);
    generated[0] = v.sphere[0];
    generated[1] = v.sphere[1];
    generated[2] = lref.tex_coord[2];
    generated[3] = lref.tex_coord[3];
    tref_mul(lref.texture_matrix, generated, strq);
}

int main(void)
{
    int failed;
    ffl_test_init();
    lref_init(sphere_map, NULL);
    init();
    reshape(64, 64);
    failed = lref_run("torus", display);
    vref_print_counts(&lref.vref);
    return failed;
}
