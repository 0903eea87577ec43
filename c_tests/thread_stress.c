/* ffl-test: fflight-only */
/*
 * Thread stress (issue 9): 16 threads, each with its own context, change state, draw
 * (immediate mode and glDrawArrays large enough to use fflight's helper threads), read back
 * through feedback and selection and query state at the same time; each thread's results
 * (a hash of every value it read) must equal a single-threaded run of the same work.
 * Then contexts are created, made current, released and destroyed by 16 threads at once,
 * with a shared pool of contexts the threads compete for: a context is never current on two
 * threads (the second fflMakeCurrent is GL_FALSE with GL_INVALID_OPERATION), and state set
 * by its holder is intact while it holds it. Last, a context current on one thread cannot
 * be destroyed by another (GL_FALSE, GL_INVALID_OPERATION, README "Contexts and threads"):
 * the first thread keeps drawing with it unharmed, and destroys it once released.
 * Run under helgrind and DRD once (README); under memcheck and ASan by make test.
 */
#define _POSIX_C_SOURCE 200112L
#include <pthread.h>
#include <string.h>
#include "ffl_test.h"

#define THREADS 16
#define ITERATIONS 4
#define ARRAY_VERTICES 33000 /* above the threaded-draw threshold (2 x 16K) */
#define SMALL_DRAW 500
#define BIG_DRAWERS 2 /* threads whose first draw is the threaded one (memcheck's time) */
#define POOL 4
#define CYCLES 150

static unsigned long long hash_bytes(unsigned long long h, const void *data, size_t n)
{
    const unsigned char *p = data;
    size_t i;
    for (i = 0; i < n; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

static unsigned next(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 8;
}

static float unit(unsigned *state) { return (float)(next(state) % 1000) / 1000.0f; }

static GLfloat positions[ARRAY_VERTICES][3], normals[ARRAY_VERTICES][3];

/* One thread's work on the current context: every value read goes into the hash. */
static unsigned long long work(unsigned seed, int big)
{
    static const GLsizei FEEDBACK = 8 * ARRAY_VERTICES + 4096; /* GL_3D_COLOR points: 8 values */
    GLfloat *feedback = malloc(sizeof(GLfloat) * (size_t)FEEDBACK);
    GLuint select[256];
    unsigned long long h = 14695981039346656037ull;
    unsigned state = seed;
    int it, k;
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_LIGHTING);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    for (it = 0; it < ITERATIONS; it++) {
        GLfloat light[4], color[4];
        GLint n, values[4];
        GLfloat matrix[16];
        int light_number = (int)(next(&state) % 8);
        for (k = 0; k < 4; k++) {
            light[k] = unit(&state) * 2.0f - 1.0f;
            color[k] = unit(&state);
        }
        glEnable(GL_LIGHT0 + (GLenum)light_number);
        glLightfv(GL_LIGHT0 + (GLenum)light_number, GL_POSITION, light);
        glLightfv(GL_LIGHT0 + (GLenum)light_number, GL_DIFFUSE, color);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, unit(&state) * 100.0f);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, (GLint)(next(&state) % 2));
        glLoadIdentity();
        glTranslatef(0.0f, 0.0f, -3.0f - unit(&state));
        glRotatef(unit(&state) * 360.0f, unit(&state), unit(&state), 1.0f);

        /* Feedback: immediate mode and a threaded glDrawArrays. */
        glFeedbackBuffer(FEEDBACK, GL_3D_COLOR, feedback);
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_TRIANGLES);
        for (k = 0; k < 30; k++) {
            glNormal3f(unit(&state), unit(&state), 1.0f);
            glVertex3f(unit(&state) - 0.5f, unit(&state) - 0.5f, unit(&state) - 0.5f);
        }
        glEnd();
        glDrawArrays(GL_POINTS, 0, big && it == 0 ? ARRAY_VERTICES : SMALL_DRAW);
        n = glRenderMode(GL_RENDER);
        h = hash_bytes(h, &n, sizeof n);
        if (n > 0)
            h = hash_bytes(h, feedback, sizeof(GLfloat) * (size_t)n);

        /* Selection: names and hits. */
        memset(select, 0, sizeof select);
        glSelectBuffer(256, select);
        glRenderMode(GL_SELECT);
        glInitNames();
        for (k = 0; k < 8; k++) {
            glPushName((GLuint)k);
            glBegin(GL_POINTS);
            glVertex3f(unit(&state) - 0.5f, unit(&state) - 0.5f, -unit(&state));
            glEnd();
            glPopName();
        }
        n = glRenderMode(GL_RENDER);
        h = hash_bytes(h, &n, sizeof n);
        if (n > 0)
            h = hash_bytes(h, select, sizeof select);

        /* Queries. */
        glGetFloatv(GL_MODELVIEW_MATRIX, matrix);
        glGetIntegerv(GL_VIEWPORT, values);
        h = hash_bytes(h, matrix, sizeof matrix);
        h = hash_bytes(h, values, sizeof values);
        glGetLightfv(GL_LIGHT0 + (GLenum)light_number, GL_POSITION, light);
        h = hash_bytes(h, light, sizeof light);
        n = (GLint)glGetError();
        h = hash_bytes(h, &n, sizeof n);
    }
    free(feedback);
    return h;
}

/* ---- 16 contexts drawing at once ---- */
struct job {
    unsigned seed;
    int big;
    unsigned long long result;
    int ok;
};

static void *drawing_thread(void *arg)
{
    struct job *job = arg;
    FflContext *context = fflCreateContext();
    job->ok = fflMakeCurrent(context) == GL_TRUE;
    job->result = work(job->seed, job->big);
    job->ok &= fflMakeCurrent(NULL) == GL_TRUE;
    job->ok &= fflDestroyContext(context) == GL_TRUE;
    return NULL;
}

/* ---- contexts created, made current, released and destroyed concurrently ---- */
static FflContext *pool[POOL];
static int pool_holder[POOL];
static pthread_mutex_t pool_lock = PTHREAD_MUTEX_INITIALIZER;
static int violations;

static void *context_thread(void *arg)
{
    int id = *(int *)arg, cycle, bad = 0;
    unsigned state = (unsigned)id * 7919u + 1u;
    for (cycle = 0; cycle < CYCLES; cycle++) {
        if (next(&state) % 2) {
            /* A private context: create, use, release, destroy. */
            FflContext *c = fflCreateContext();
            GLfloat index = -1.0f;
            bad |= (fflMakeCurrent(c) != GL_TRUE) << 0;
            glClearIndex((GLfloat)id);
            glGetFloatv(GL_INDEX_CLEAR_VALUE, &index);
            bad |= (index != (GLfloat)id) << 1;
            bad |= (fflMakeCurrent(NULL) != GL_TRUE) << 2;
            bad |= (fflDestroyContext(c) != GL_TRUE) << 3;
        } else {
            /* A shared one: taken only when no other thread has it current. */
            int slot = (int)(next(&state) % POOL), k;
            if (fflMakeCurrent(pool[slot]) == GL_TRUE) {
                GLfloat index = -1.0f;
                pthread_mutex_lock(&pool_lock);
                if (pool_holder[slot] != -1)
                    violations++;
                pool_holder[slot] = id;
                pthread_mutex_unlock(&pool_lock);
                glClearIndex((GLfloat)id);
                for (k = 0; k < 20; k++)
                    glGetFloatv(GL_INDEX_CLEAR_VALUE, &index);
                bad |= (index != (GLfloat)id) << 4;
                pthread_mutex_lock(&pool_lock);
                pool_holder[slot] = -1;
                pthread_mutex_unlock(&pool_lock);
                bad |= (fflMakeCurrent(NULL) != GL_TRUE) << 5;
            } else {
                /* Refused: GL_INVALID_OPERATION on this thread's own context. */
                bad |= (glGetError() != GL_INVALID_OPERATION) << 6;
            }
        }
    }
    *(int *)arg = !bad;
    if (bad)
        printf("context thread %d: bad %d\n", id, bad);
    return NULL;
}

/* ---- a context current on one thread, destroyed (refused) from another ---- */
static FflContext *held;
static pthread_mutex_t step_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t step_cond = PTHREAD_COND_INITIALIZER;
static int step;

static void wait_step(int s)
{
    pthread_mutex_lock(&step_lock);
    while (step < s)
        pthread_cond_wait(&step_cond, &step_lock);
    pthread_mutex_unlock(&step_lock);
}

static void set_step(int s)
{
    pthread_mutex_lock(&step_lock);
    step = s;
    pthread_cond_broadcast(&step_cond);
    pthread_mutex_unlock(&step_lock);
}

static void *holder_thread(void *arg)
{
    int ok = fflMakeCurrent(held) == GL_TRUE;
    GLfloat buf[64];
    GLint n;
    glClearIndex(5.0f);
    set_step(1);
    wait_step(2); /* the other thread tried to destroy it and to make it current */
    glViewport(0, 0, 64, 64);
    glFeedbackBuffer(64, GL_3D, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glEnd();
    n = glRenderMode(GL_RENDER);
    ok &= n == 4 && glGetError() == GL_NO_ERROR;
    ok &= fflMakeCurrent(NULL) == GL_TRUE;
    *(int *)arg = ok;
    return NULL;
}

int main(void)
{
    pthread_t threads[THREADS];
    struct job jobs[THREADS];
    int ids[THREADS], k, failures = 0, ok;
    GLfloat index = 0.0f;
    for (k = 0; k < ARRAY_VERTICES; k++) {
        positions[k][0] = (GLfloat)(k % 61) / 30.0f - 1.0f;
        positions[k][1] = (GLfloat)(k % 53) / 26.0f - 1.0f;
        positions[k][2] = (GLfloat)(k % 7) / 7.0f - 0.5f;
        normals[k][0] = 0.0f;
        normals[k][1] = (GLfloat)(k % 3) / 3.0f;
        normals[k][2] = 1.0f;
    }

    /* The single-threaded reference, then 16 threads at once. */
    for (k = 0; k < THREADS; k++) {
        FflContext *c = fflCreateContext();
        jobs[k].seed = (unsigned)k * 2654435761u + 1u;
        jobs[k].big = k < BIG_DRAWERS;
        fflMakeCurrent(c);
        jobs[k].result = work(jobs[k].seed, jobs[k].big);
        fflMakeCurrent(NULL);
        fflDestroyContext(c);
    }
    {
        struct job concurrent[THREADS];
        for (k = 0; k < THREADS; k++) {
            concurrent[k].seed = jobs[k].seed;
            concurrent[k].big = jobs[k].big;
            if (pthread_create(&threads[k], NULL, drawing_thread, &concurrent[k]) != 0)
                return 1;
        }
        for (k = 0; k < THREADS; k++) {
            pthread_join(threads[k], NULL);
            ok = concurrent[k].ok && concurrent[k].result == jobs[k].result;
            printf("drawing thread %d same as alone %d\n", k, ok);
            failures += !ok;
        }
    }

    /* Contexts created, made current, released and destroyed concurrently. */
    for (k = 0; k < POOL; k++) {
        pool[k] = fflCreateContext();
        pool_holder[k] = -1;
    }
    for (k = 0; k < THREADS; k++) {
        ids[k] = k;
        if (pthread_create(&threads[k], NULL, context_thread, &ids[k]) != 0)
            return 1;
    }
    ok = 1;
    for (k = 0; k < THREADS; k++) {
        pthread_join(threads[k], NULL);
        ok &= ids[k];
    }
    printf("context threads ok %d, a context current on two threads %d times\n", ok, violations);
    failures += !ok;
    failures += violations != 0;
    for (k = 0; k < POOL; k++)
        failures += fflDestroyContext(pool[k]) != GL_TRUE;

    /* Destroying (or making current) a context current on another thread is refused. */
    held = fflCreateContext();
    ids[0] = 0;
    if (pthread_create(&threads[0], NULL, holder_thread, &ids[0]) != 0)
        return 1;
    wait_step(1);
    glGetError();
    ok = fflDestroyContext(held) == GL_FALSE && glGetError() == GL_INVALID_OPERATION;
    ok &= fflMakeCurrent(held) == GL_FALSE && glGetError() == GL_INVALID_OPERATION;
    set_step(2);
    pthread_join(threads[0], NULL);
    ok &= ids[0];
    /* Released: now it can be made current here, still holding the holder's state. */
    ok &= fflMakeCurrent(held) == GL_TRUE;
    glGetFloatv(GL_INDEX_CLEAR_VALUE, &index);
    ok &= index == 5.0f;
    ok &= fflDestroyContext(held) == GL_TRUE && glGetError() == GL_NO_ERROR;
    printf("destroy of a context current elsewhere refused, holder unharmed %d\n", ok);
    failures += !ok;
    return failures;
}
