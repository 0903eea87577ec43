/* ffl-test: differential */
/*
 * The GL 1.4 current attributes and raster commands (§2.7, §2.13): the
 * current secondary color from every glSecondaryColor3 form (integer forms
 * normalized per table 2.9, alpha 1), the current fog coordinate, and
 * glWindowPos in every form: window x and y as given, z mapped into the depth
 * range and clamped to it, the raster colors the current ones clamped to
 * [0, 1] with lighting on (no lighting, no transformation), the texture
 * coordinate untransformed, the raster distance 0 or the fog coordinate when
 * it is the fog source (for glRasterPos too); a hit in selection mode;
 * GL_INVALID_OPERATION between glBegin and glEnd.
 */
#include "ffl_test.h"

static void raster(const char *what)
{
    GLfloat v[4];
    GLboolean valid;
    printf("%s", what);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, v);
    ffl_pfv("xyzw", v, 4);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, v);
    ffl_pfv("color", v, 4);
    glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, v);
    ffl_pfv("secondary", v, 4);
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, v);
    ffl_pfv("tex", v, 4);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, v);
    ffl_pfv("distance", v, 1);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    printf(" valid %d error %s\n", (int)valid, ffl_error_name(glGetError()));
}

static void secondary(const char *what)
{
    GLfloat v[4];
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
    printf("%s", what);
    ffl_pfv("secondary", v, 4);
    printf(" error %s\n", ffl_error_name(glGetError()));
}

int main(void)
{
    static const GLbyte bv[3] = { -128, 0, 127 };
    static const GLshort sv[3] = { -32768, 1000, 32767 };
    static const GLint iv[3] = { -2147483647 - 1, 5, 2147483647 };
    static const GLfloat fv[3] = { -0.5f, 0.25f, 2.0f };
    static const GLdouble dv[3] = { 0.125, 0.5, 0.75 };
    static const GLubyte ubv[3] = { 0, 128, 255 };
    static const GLushort usv[3] = { 0, 40000, 65535 };
    static const GLuint uiv[3] = { 0, 3000000000u, 4294967295u };
    static const GLshort wsv[3] = { 7, -3, 1 };
    static const GLint wiv[3] = { 100, 200, 0 };
    static const GLfloat wfv[3] = { 10.25f, 20.5f, 0.5f };
    static const GLdouble wdv[3] = { -1.5, 2.25, 0.75 };
    static const GLfloat fog = 2.5f;
    static const GLdouble fogd = -4.0;
    GLfloat v[4];
    GLuint records[16];
    GLint hits;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glDepthRange(0.25, 0.75);

    secondary("initial");
    glSecondaryColor3b(-128, 0, 127);
    secondary("3b");
    glSecondaryColor3bv(bv);
    secondary("3bv");
    glSecondaryColor3s(-32768, 1000, 32767);
    secondary("3s");
    glSecondaryColor3sv(sv);
    secondary("3sv");
    glSecondaryColor3i(-2147483647 - 1, 5, 2147483647);
    secondary("3i");
    glSecondaryColor3iv(iv);
    secondary("3iv");
    glSecondaryColor3f(-0.5f, 0.25f, 2.0f);
    secondary("3f");
    glSecondaryColor3fv(fv);
    secondary("3fv");
    glSecondaryColor3d(0.125, 0.5, 0.75);
    secondary("3d");
    glSecondaryColor3dv(dv);
    secondary("3dv");
    glSecondaryColor3ub(0, 128, 255);
    secondary("3ub");
    glSecondaryColor3ubv(ubv);
    secondary("3ubv");
    glSecondaryColor3us(0, 40000, 65535);
    secondary("3us");
    glSecondaryColor3usv(usv);
    secondary("3usv");
    glSecondaryColor3ui(0, 3000000000u, 4294967295u);
    secondary("3ui");
    glSecondaryColor3uiv(uiv);
    secondary("3uiv");

    glGetFloatv(GL_CURRENT_FOG_COORD, v);
    printf("fog_coord initial");
    ffl_pfv("coord", v, 1);
    glFogCoordf(1.5f);
    glGetFloatv(GL_CURRENT_FOG_COORD, v);
    ffl_pfv(" f coord", v, 1);
    glFogCoordd(-2.0);
    glGetFloatv(GL_CURRENT_FOG_COORD, v);
    ffl_pfv(" d coord", v, 1);
    glFogCoordfv(&fog);
    glGetFloatv(GL_CURRENT_FOG_COORD, v);
    ffl_pfv(" fv coord", v, 1);
    glFogCoorddv(&fogd);
    glGetFloatv(GL_CURRENT_FOG_COORD, v);
    ffl_pfv(" dv coord", v, 1);
    printf(" error %s\n", ffl_error_name(glGetError()));

    /* Lighting on, a texture matrix and a modelview: glWindowPos ignores all. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMatrixMode(GL_TEXTURE);
    glScalef(2, 2, 2);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(5, 5, 5);
    glColor4f(1.5f, -0.25f, 0.5f, 2.0f);
    glSecondaryColor3f(0.25f, 3.0f, -1.0f);
    glTexCoord4f(0.5f, 1.5f, 2.5f, 3.5f);
    glWindowPos2s(3, 4);
    raster("2s");
    glWindowPos2sv(wsv);
    raster("2sv");
    glWindowPos2i(-5, 6);
    raster("2i");
    glWindowPos2iv(wiv);
    raster("2iv");
    glWindowPos2f(1.75f, 2.5f);
    raster("2f");
    glWindowPos2fv(wfv);
    raster("2fv");
    glWindowPos2d(3.5, -4.5);
    raster("2d");
    glWindowPos2dv(wdv);
    raster("2dv");
    glWindowPos3s(1, 2, 1);
    raster("3s");
    glWindowPos3sv(wsv);
    raster("3sv");
    glWindowPos3i(1, 2, -1);
    raster("3i");
    glWindowPos3iv(wiv);
    raster("3iv");
    glWindowPos3f(1, 2, 0.5f);
    raster("3f");
    glWindowPos3fv(wfv);
    raster("3fv");
    glWindowPos3d(1, 2, 0.25);
    raster("3d");
    glWindowPos3dv(wdv);
    raster("3dv");

    /* The fog coordinate as the fog source sets the raster distance. */
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogCoordf(6.5f);
    glWindowPos2f(8, 9);
    raster("fog_source_window");
    glRasterPos3f(0, 0, -6);
    raster("fog_source_raster");
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    glRasterPos3f(0, 0, -6);
    raster("depth_source_raster");

    /* Selection: a window position is a hit. */
    glSelectBuffer(16, records);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(9);
    glWindowPos3f(1, 1, 0.5f);
    hits = glRenderMode(GL_RENDER);
    printf("select hits %d names %u", (int)hits, hits > 0 ? records[3] : 0u);
    printf(" error %s\n", ffl_error_name(glGetError()));

    glBegin(GL_POINTS);
    glWindowPos2f(1, 1);
    glEnd();
    printf("inside_begin_end error %s\n", ffl_error_name(glGetError()));
    glBegin(GL_POINTS);
    glSecondaryColor3f(0.5f, 0.5f, 0.5f);
    glFogCoordf(1.0f);
    glEnd();
    printf("attributes_inside error %s\n", ffl_error_name(glGetError()));
    return 0;
}
