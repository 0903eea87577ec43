/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: the scalar forms glLight{fi}, glMaterial{fi} and
 * glLightModel{fi} with a pname that takes several values (§2.14.2: the
 * scalar forms accept only the single-valued parameters, tables 2.10-2.12;
 * any other pname is GL_INVALID_ENUM and the command does nothing). Mesa
 * accepts them, reading the one value given and zero-filling the rest:
 * glLightf(GL_LIGHT0, GL_AMBIENT, 0.5) makes the ambient (0.5, 0, 0, 0).
 * Each call prints the error and the state after it, against the spec's
 * (error 1280 = GL_INVALID_ENUM, state unchanged); the single-valued pnames
 * work in both (shown for contrast).
 */
#include "ffl_test.h"

/* "<what> error <e> <label> v0.. ref error <e'> <label> v0'.." */
static void report(const char *what, GLenum want_error, const char *label, const GLfloat *got,
                   const GLfloat *want, int n)
{
    GLenum e = glGetError();
    printf("%s error %u", what, (unsigned)e);
    ffl_pfv(label, got, n);
    printf(" ref error %u", (unsigned)want_error);
    ffl_pfv(label, want, n);
    printf("\n");
}

int main(void)
{
    static const GLfloat light_ambient[4] = { 0, 0, 0, 1 };
    static const GLfloat light0_diffuse[4] = { 1, 1, 1, 1 };
    static const GLfloat position[4] = { 0, 0, 1, 0 };
    static const GLfloat spot_direction[3] = { 0, 0, -1 };
    static const GLfloat mat_ambient[4] = { 0.2f, 0.2f, 0.2f, 1 };
    static const GLfloat mat_diffuse[4] = { 0.8f, 0.8f, 0.8f, 1 };
    static const GLfloat mat_emission[4] = { 0, 0, 0, 1 };
    static const GLfloat model_ambient[4] = { 0.2f, 0.2f, 0.2f, 1 };
    static const GLfloat five[1] = { 5 }, thirty[1] = { 30 };
    GLfloat v[4];

    ffl_test_init();
    glGetError();

    glLightf(GL_LIGHT0, GL_AMBIENT, 0.5f);
    glGetLightfv(GL_LIGHT0, GL_AMBIENT, v);
    report("lightf_ambient", GL_INVALID_ENUM, "ambient", v, light_ambient, 4);
    glLighti(GL_LIGHT0, GL_DIFFUSE, 1);
    glGetLightfv(GL_LIGHT0, GL_DIFFUSE, v);
    report("lighti_diffuse", GL_INVALID_ENUM, "diffuse", v, light0_diffuse, 4);
    glLightf(GL_LIGHT0, GL_POSITION, 0.5f);
    glGetLightfv(GL_LIGHT0, GL_POSITION, v);
    report("lightf_position", GL_INVALID_ENUM, "position", v, position, 4);
    glLightf(GL_LIGHT0, GL_SPOT_DIRECTION, 0.5f);
    glGetLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, v);
    report("lightf_spot_direction", GL_INVALID_ENUM, "direction", v, spot_direction, 3);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 5);
    glGetLightfv(GL_LIGHT0, GL_SPOT_EXPONENT, v);
    report("lightf_spot_exponent", GL_NO_ERROR, "exponent", v, five, 1);

    glMaterialf(GL_FRONT, GL_AMBIENT, 0.5f);
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
    report("materialf_ambient", GL_INVALID_ENUM, "ambient", v, mat_ambient, 4);
    glMateriali(GL_BACK, GL_EMISSION, 1);
    glGetMaterialfv(GL_BACK, GL_EMISSION, v);
    report("materiali_emission", GL_INVALID_ENUM, "emission", v, mat_emission, 4);
    glMaterialf(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, 0.5f);
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
    report("materialf_ambient_and_diffuse", GL_INVALID_ENUM, "diffuse", v, mat_diffuse, 4);
    glMaterialf(GL_FRONT, GL_SHININESS, 30);
    glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
    report("materialf_shininess", GL_NO_ERROR, "shininess", v, thirty, 1);

    glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.5f);
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
    report("lightmodelf_ambient", GL_INVALID_ENUM, "ambient", v, model_ambient, 4);
    glLightModeli(GL_LIGHT_MODEL_AMBIENT, 1);
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
    report("lightmodeli_ambient", GL_INVALID_ENUM, "ambient", v, model_ambient, 4);
    return 0;
}
