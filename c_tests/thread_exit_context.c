/* ffl-test: fflight-only */
/*
 * Threads that use GL and exit without destroying anything: each gets its own default
 * context on its first call (set state, light a vertex through feedback, read the error
 * flag), and the context goes away with the thread. Under valgrind (make test-valgrind)
 * this must leave no definite leak; here each thread checks its own feedback and that it
 * did not see another thread's state.
 */
#define _POSIX_C_SOURCE 200112L
#include <pthread.h>
#include "ffl_test.h"

#define THREADS 4

static void *work(void *arg)
{
    int id = *(int *)arg;
    GLfloat buf[8], diffuse[4];
    GLint n;
    diffuse[0] = 0.2f * (float)(id + 1);
    diffuse[1] = diffuse[2] = 0.0f;
    diffuse[3] = 1.0f;
    glViewport(0, 0, 64, 64);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glFeedbackBuffer(8, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glEnd();
    n = glRenderMode(GL_RENDER);
    /* Red: 0.2 * 0.2 ambient + the diffuse, from this thread's own material only. */
    *(int *)arg = n == 8 && fabs(buf[4] - (0.04 + diffuse[0])) < 1e-6 && glGetError() == 0;
    return NULL;
}

int main(void)
{
    pthread_t threads[THREADS];
    int results[THREADS], k, failures = 0;
    for (k = 0; k < THREADS; k++) {
        results[k] = k;
        if (pthread_create(&threads[k], NULL, work, &results[k]) != 0)
            return 1;
    }
    for (k = 0; k < THREADS; k++) {
        pthread_join(threads[k], NULL);
        printf("thread %d ok %d\n", k, results[k]);
        failures += !results[k];
    }
    return failures;
}
