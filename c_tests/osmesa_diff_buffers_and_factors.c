/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: state commands of the per-fragment, pixel and fog groups that GL 1.5
 * rejects or defines and Mesa (a GL 4.x implementation) treats otherwise. Each line prints
 * the build's result and, after `ref`, GL 1.5's:
 * - glDrawBuffer(GL_BACK) and glReadBuffer(GL_BACK) on a single-buffered framebuffer:
 *   GL_INVALID_OPERATION, no such buffer (§4.2.1, §4.3.2); Mesa maps BACK to the front
 *   buffer, as later GL versions do for single-buffered windows.
 * - glReadBuffer(GL_FRONT_AND_BACK): GL_INVALID_ENUM (§4.3.2 lists no FRONT_AND_BACK);
 *   Mesa reads the front buffer.
 * - glBlendFunc with GL_SRC_ALPHA_SATURATE as the destination: GL_INVALID_ENUM (table 4.2);
 *   Mesa accepts it (ARB_blend_func_extended).
 * - glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, ...): GL_INVALID_VALUE, the maps indexed by an
 *   index need a power-of-two size (§3.6.3); Mesa checks S_TO_S to I_TO_A only.
 * - glPixelStoref(GL_PACK_SWAP_BYTES, 0.25): TRUE, a boolean is false only for 0 (§3.6.1);
 *   Mesa rounds the float to an integer first (FALSE).
 * - glGetPixelMapuiv(GL_PIXEL_MAP_S_TO_S): the stencil indices (5, 9); Mesa returns the
 *   bit patterns of the floats it stores them as.
 * - glFogf(GL_FOG_COLOR, x): fflight's rule for every scalar form given a vector pname
 *   (glLightf, glMaterialf, glLightModelf in osmesa_diff_scalar_pnames.c; glPointParameterf)
 *   is GL_INVALID_ENUM; Mesa sets the color to (x, 0, 0, 0).
 */
#include "ffl_test.h"

static void check_error(const char *what, GLenum expected)
{
    printf("%s err %d ref err %d\n", what, (int)glGetError(), (int)expected);
}

int main(void)
{
    static const GLfloat three[3] = { 1, 2, 3 };
    static const GLuint stencils[2] = { 5u, 9u };
    GLuint got[2] = { 0u, 0u };
    GLboolean swap = 7;
    GLfloat color[4] = { -1, -1, -1, -1 };

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    glDrawBuffer(GL_BACK);
    check_error("draw_buffer_back", GL_INVALID_OPERATION);
    glReadBuffer(GL_BACK);
    check_error("read_buffer_back", GL_INVALID_OPERATION);
    glReadBuffer(GL_FRONT_AND_BACK);
    check_error("read_buffer_front_and_back", GL_INVALID_ENUM);
    glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE);
    check_error("blend_dst_src_alpha_saturate", GL_INVALID_ENUM);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, three);
    check_error("pixel_map_i_to_i_size_3", GL_INVALID_VALUE);

    glPixelStoref(GL_PACK_SWAP_BYTES, 0.25f);
    glGetBooleanv(GL_PACK_SWAP_BYTES, &swap);
    printf("pixel_store_f_boolean b %d ref b 1\n", (int)swap);

    glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, stencils);
    glGetPixelMapuiv(GL_PIXEL_MAP_S_TO_S, got);
    printf("get_pixel_map_uiv_s_to_s i %u %u ref i 5 9\n", got[0], got[1]);

    glFogf(GL_FOG_COLOR, 0.5f);
    check_error("fogf_color", GL_INVALID_ENUM);
    glGetFloatv(GL_FOG_COLOR, color);
    printf("fog_color");
    ffl_pfv("f", color, 4);
    printf(" ref f 0 0 0 0\n");
    return 0;
}
