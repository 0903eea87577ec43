/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: state glPopAttrib and glPopClientAttrib leave as it is where the
 * state tables (6.10, 6.11, 6.27, 6.7) and §2.14.3, §2.9 say otherwise. Each line prints the
 * build's result and, after `ref`, GL 1.5's:
 * - GL_LIGHTi (attribute lighting/enable) after glPopAttrib(GL_ENABLE_BIT): restored;
 *   OSMesa keeps the value set after the push (it restores them with GL_LIGHTING_BIT, as
 *   the lines after show).
 * - GL_COLOR_SUM (fog/enable) after glPopAttrib(GL_ENABLE_BIT): restored; OSMesa keeps it.
 * - GL_FOG_COORD_SRC (fog) after glPopAttrib(GL_FOG_BIT): restored; OSMesa keeps it.
 * - GL_GENERATE_MIPMAP_HINT (hint) after glPopAttrib(GL_HINT_BIT): restored; OSMesa keeps it.
 * - With GL_COLOR_MATERIAL enabled, the tracked material after glPopAttrib(GL_CURRENT_BIT)
 *   is the restored current color (§2.14.3: the material tracks the current color); OSMesa
 *   keeps the last glColor's.
 * - A buffer object deleted while its binding is on the client stack: glPopClientAttrib
 *   restores binding 0 (§2.9: bindings to a deleted object revert to 0) and the name stays
 *   unused; OSMesa binds the name again, making a new empty object (glIsBuffer true).
 */
#include "ffl_test.h"

static void print_enabled(const char *what, GLenum cap, int expected)
{
    printf("%s b %d ref b %d\n", what, (int)glIsEnabled(cap), expected);
}

static void print_int(const char *what, GLenum pname, GLint expected)
{
    GLint v = -7;
    glGetIntegerv(pname, &v);
    printf("%s i %d ref i %d\n", what, (int)v, (int)expected);
}

int main(void)
{
    static const GLfloat data[3] = { 0, 0, 0 };
    GLfloat diffuse[4];
    GLuint buffer;

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    glEnable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glPopAttrib();
    print_enabled("enable_bit_light0", GL_LIGHT0, 1);
    print_enabled("enable_bit_light1", GL_LIGHT1, 0);

    glEnable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glPushAttrib(GL_LIGHTING_BIT);
    glDisable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glPopAttrib();
    print_enabled("lighting_bit_light0", GL_LIGHT0, 1);
    print_enabled("lighting_bit_light1", GL_LIGHT1, 0);

    glEnable(GL_COLOR_SUM);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_COLOR_SUM);
    glPopAttrib();
    print_enabled("enable_bit_color_sum", GL_COLOR_SUM, 1);

    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glPushAttrib(GL_FOG_BIT);
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    glPopAttrib();
    print_int("fog_bit_fog_coord_src", GL_FOG_COORD_SRC, GL_FOG_COORD);

    glHint(GL_GENERATE_MIPMAP_HINT, GL_FASTEST);
    glPushAttrib(GL_HINT_BIT);
    glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
    glPopAttrib();
    print_int("hint_bit_generate_mipmap", GL_GENERATE_MIPMAP_HINT, GL_FASTEST);

    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.9f, 0.8f, 0.7f, 0.6f);
    glPushAttrib(GL_CURRENT_BIT);
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    glPopAttrib();
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    printf("current_bit_tracked_diffuse");
    ffl_pfv("f", diffuse, 4);
    printf(" ref f 0.9 0.8 0.7 0.6\n");
    glDisable(GL_COLOR_MATERIAL);

    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, 0, NULL);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDeleteBuffers(1, &buffer);
    glPopClientAttrib();
    print_int("deleted_buffer_array_binding", GL_ARRAY_BUFFER_BINDING, 0);
    print_int("deleted_buffer_vertex_array_binding", GL_VERTEX_ARRAY_BUFFER_BINDING, 0);
    printf("deleted_buffer_is_buffer b %d ref b 0\n", (int)glIsBuffer(buffer));
    printf("errors i %d ref i 0\n", (int)glGetError());
    return 0;
}
