#include "tl_sky.h"

#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

#define PI 3.14159265358979323846

void tl_sky_atmosphere_of(const tl_scene *s, tl_atmosphere *a)
{
    memset(a, 0, sizeof *a);
    a->ground_radius = s->sky.planet_radius * 1000.0;
    a->top_radius = a->ground_radius + s->sky.atmosphere_height * 1000.0;
    const double rayleigh[3] = {5.802e-6, 13.558e-6, 33.1e-6};
    const double ozone[3] = {0.650e-6, 1.881e-6, 0.085e-6};
    for (int c = 0; c < 3; c++) {
        a->rayleigh[c] = rayleigh[c];
        a->ozone[c] = ozone[c] * s->sky.ozone;
    }
    a->rayleigh_height = 8000.0;
    a->mie_scattering = 3.996e-6 * s->sky.turbidity;
    a->mie_absorption = 4.40e-6 * s->sky.turbidity;
    a->mie_height = 1200.0;
    a->mie_g = 0.8;
    a->ozone_center = 25000.0;
    a->ozone_width = 15000.0;
    a->ground_albedo = s->sky.ground_albedo;
}

/* Scattering and extinction coefficients at height h above the ground. */
static void medium(const tl_atmosphere *a, double h, double ray_s[3], double *mie_s, double ext[3])
{
    double dr = exp(-h / a->rayleigh_height), dm = exp(-h / a->mie_height);
    double dozone = fmax(0.0, 1.0 - fabs(h - a->ozone_center) / a->ozone_width);
    *mie_s = a->mie_scattering * dm;
    for (int c = 0; c < 3; c++) {
        ray_s[c] = a->rayleigh[c] * dr;
        ext[c] = ray_s[c] + (a->mie_scattering + a->mie_absorption) * dm + a->ozone[c] * dozone;
    }
}

static double to_top(const tl_atmosphere *a, double r, double mu)
{
    double disc = r * r * (mu * mu - 1.0) + a->top_radius * a->top_radius;
    return fmax(0.0, -r * mu + sqrt(fmax(disc, 0.0)));
}

/* Distance to the ground along mu, or -1 when the ray misses it. */
static double to_ground(const tl_atmosphere *a, double r, double mu)
{
    double disc = r * r * (mu * mu - 1.0) + a->ground_radius * a->ground_radius;
    if (mu >= 0.0 || disc < 0.0)
        return -1.0;
    return fmax(0.0, -r * mu - sqrt(disc));
}

void tl_sky_transmittance(const tl_atmosphere *a, double r, double mu, int steps, double out[3])
{
    if (to_ground(a, r, mu) >= 0.0) { /* the planet's shadow */
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    /* Steps grow with distance (t = d·x²): the air is densest at the start
     * of the rays that matter (low ones). */
    double d = to_top(a, r, mu), depth[3] = {0, 0, 0};
    for (int i = 0; i < steps; i++) {
        double x = (i + 0.5) / steps, t = d * x * x, dt = d * 2.0 * x / steps;
        double rt = sqrt(r * r + t * t + 2.0 * r * mu * t);
        double rs[3], ms, ext[3];
        medium(a, rt - a->ground_radius, rs, &ms, ext);
        for (int c = 0; c < 3; c++)
            depth[c] += ext[c] * dt;
    }
    for (int c = 0; c < 3; c++)
        out[c] = exp(-depth[c]);
}

/* ---- the transmittance table (Bruneton's mapping: fine at the horizon) ---- */

static void transmittance_uv(const tl_atmosphere *a, double r, double mu, double *u, double *v)
{
    double H = sqrt(a->top_radius * a->top_radius - a->ground_radius * a->ground_radius);
    double rho = sqrt(fmax(r * r - a->ground_radius * a->ground_radius, 0.0));
    double d = to_top(a, r, mu), d_min = a->top_radius - r, d_max = rho + H;
    *u = d_max > d_min ? (d - d_min) / (d_max - d_min) : 0.0;
    *v = rho / H;
}

/* x held in [0, hi], NaN to 0 (as fmin(fmax(x, 0), hi), which libm does
 * not inline: it was a tenth of a sky-view table's time). */
static double clamp_index(double x, double hi)
{
    x = x > 0.0 ? x : 0.0;
    return x < hi ? x : hi;
}

/* Where v falls between a table's rows: computed once where many lookups
 * share a row (the sky-view table's steps). */
typedef struct lut_row {
    int y0, y1;
    double fy;
} lut_row;

static lut_row lut_row_at(int h, double v)
{
    double y = clamp_index(v * h - 0.5, h - 1.0);
    lut_row r = {(int)y, 0, 0.0};
    r.y1 = r.y0 + 1 < h ? r.y0 + 1 : r.y0;
    r.fy = y - r.y0;
    return r;
}

static void bilinear_row(const float *table, int w, const lut_row *row, double u, double out[3])
{
    double x = clamp_index(u * w - 0.5, w - 1.0);
    int x0 = (int)x, x1 = x0 + 1 < w ? x0 + 1 : x0;
    double fx = x - x0, fy = row->fy;
    const float *r0 = table + row->y0 * w * 3, *r1 = table + row->y1 * w * 3;
    for (int c = 0; c < 3; c++) {
        double a = r0[x0 * 3 + c], b = r0[x1 * 3 + c];
        double d = r1[x0 * 3 + c], e = r1[x1 * 3 + c];
        out[c] = (a * (1 - fx) + b * fx) * (1 - fy) + (d * (1 - fx) + e * fx) * fy;
    }
}

static void bilinear(const float *table, int w, int h, double u, double v, double out[3])
{
    lut_row row = lut_row_at(h, v);
    bilinear_row(table, w, &row, u, out);
}

static void lut_transmittance(const tl_sky_luts *l, double r, double mu, double out[3])
{
    if (to_ground(&l->atmosphere, r, mu) >= 0.0) {
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    double u, v;
    transmittance_uv(&l->atmosphere, r, mu, &u, &v);
    bilinear(&l->transmittance[0][0][0], TL_SKY_TRANSMITTANCE_W, TL_SKY_TRANSMITTANCE_H, u, v, out);
}

/* ---- the tables' rows, over the machine's cores ---- */

/* Every table's rows are independent, and the tables are built while the
 * GPU waits for them: the sky-view table whenever the sun or the camera's
 * height moves (every frame of most cutscenes), all three at the first
 * frame and whenever the atmosphere changes. Rows go to one thread per
 * core, interleaved (a table's costly rows lie together), and each row's
 * result is the same whatever the number of threads. */
#define SKY_MAX_THREADS 16

typedef void (*row_fn)(void *ctx, int row);

typedef struct row_job {
    row_fn fn;
    void *ctx;
    int rows, first, stride;
} row_job;

static void *run_rows(void *arg)
{
    const row_job *job = arg;
    for (int j = job->first; j < job->rows; j += job->stride)
        job->fn(job->ctx, j);
    return NULL;
}

static void parallel_rows(int rows, row_fn fn, void *ctx)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int threads = cores < 1 ? 1 : cores > SKY_MAX_THREADS ? SKY_MAX_THREADS : (int)cores;
    row_job jobs[SKY_MAX_THREADS];
    pthread_t ids[SKY_MAX_THREADS];
    int started[SKY_MAX_THREADS] = {0};
    /* Signals stay with the calling thread (tideline render's SIGINT and
     * SIGTERM stop the run from there), as with render's writers. */
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &old);
    for (int k = 0; k < threads; k++) {
        jobs[k] = (row_job){fn, ctx, rows, k, threads};
        /* The calling thread takes job 0, and any whose thread could
         * not start (below). */
        if (k > 0)
            started[k] = pthread_create(&ids[k], NULL, run_rows, &jobs[k]) == 0;
    }
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    run_rows(&jobs[0]);
    for (int k = 1; k < threads; k++) {
        if (started[k])
            pthread_join(ids[k], NULL);
        else
            run_rows(&jobs[k]);
    }
}

static void transmittance_row(void *ctx, int j)
{
    tl_sky_luts *l = ctx;
    const tl_atmosphere *a = &l->atmosphere;
    double H = sqrt(a->top_radius * a->top_radius - a->ground_radius * a->ground_radius);
    double rho = H * (j + 0.5) / TL_SKY_TRANSMITTANCE_H;
    double r = sqrt(rho * rho + a->ground_radius * a->ground_radius);
    for (int i = 0; i < TL_SKY_TRANSMITTANCE_W; i++) {
        double d_min = a->top_radius - r, d_max = rho + H;
        double d = d_min + (i + 0.5) / TL_SKY_TRANSMITTANCE_W * (d_max - d_min);
        double mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
        mu = fmin(fmax(mu, -1.0), 1.0);
        /* Just above the horizon: never the ground's shadow here. */
        double t[3], disc = r * r * (mu * mu - 1.0) + a->ground_radius * a->ground_radius;
        if (mu < 0.0 && disc >= 0.0)
            mu = -sqrt(fmax(0.0, 1.0 - a->ground_radius * a->ground_radius / (r * r))) + 1e-9;
        tl_sky_transmittance(a, r, mu, 64, t);
        for (int c = 0; c < 3; c++)
            l->transmittance[j][i][c] = (float)t[c];
    }
}

/* ---- multiple scattering (Hillaire's psi_ms) ---- */

typedef void (*transmittance_fn)(const void *ctx, double r, double mu, double out[3]);

static void direct_transmittance(const void *ctx, double r, double mu, double out[3])
{
    tl_sky_transmittance(ctx, r, mu, 48, out);
}

static void table_transmittance(const void *ctx, double r, double mu, double out[3])
{
    lut_transmittance(ctx, r, mu, out);
}

/* Light off the Lambertian ground where a ray from radius r along dir
 * meets it after d metres, through the optical depth gathered on the way. */
static void add_ground(const tl_atmosphere *a, transmittance_fn tr, const void *ctx,
                       const double dir[3], double r, double d, const double sun[3],
                       const double depth[3], double L[3])
{
    double g[3] = {dir[0] * d, r + dir[1] * d, dir[2] * d};
    double rg = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    double mu_g = (g[0] * sun[0] + g[1] * sun[1] + g[2] * sun[2]) / rg, ts[3];
    tr(ctx, rg, mu_g, ts);
    for (int c = 0; c < 3; c++)
        L[c] += exp(-depth[c]) * ts[c] * fmax(mu_g, 0.0) * a->ground_albedo / PI;
}

/* psi_ms at radius r (below): its rays over a sphere of directions and
 * what they gather that does not depend on the sun, traced once for all
 * the sun angles at that radius (a row of the table). */
#define MS_MAX_DIRS  64
#define MS_MAX_STEPS 24

typedef struct ms_rays {
    double r;
    int dirs, steps;
    struct {
        double dir[3], dist, dt, depth[3]; /* depth: optical depth to its end */
        int ground;                        /* it ends on the ground */
    } ray[MS_MAX_DIRS];
    struct {
        double p[3], rp, lit[3]; /* the step's point; transmittance × scattering */
    } step[MS_MAX_DIRS][MS_MAX_STEPS];
    double f[3]; /* the share of light a scattering event passes on, summed */
} ms_rays;

static void ms_trace(const tl_atmosphere *a, double r, int dirs, int steps, ms_rays *m)
{
    m->r = r;
    m->dirs = dirs;
    m->steps = steps;
    m->f[0] = m->f[1] = m->f[2] = 0.0;
    for (int k = 0; k < dirs; k++) {
        /* Fibonacci sphere. */
        double y = 1.0 - 2.0 * (k + 0.5) / dirs, rad = sqrt(fmax(0.0, 1.0 - y * y));
        double phi = k * 2.399963229728653;
        double *dir = m->ray[k].dir, *depth = m->ray[k].depth;
        dir[0] = rad * cos(phi);
        dir[1] = y;
        dir[2] = rad * sin(phi);
        double ground = to_ground(a, r, y);
        m->ray[k].ground = ground >= 0.0;
        double d = ground >= 0.0 ? ground : to_top(a, r, y), dt = d / steps;
        m->ray[k].dist = d;
        m->ray[k].dt = dt;
        depth[0] = depth[1] = depth[2] = 0.0;
        for (int i = 0; i < steps; i++) {
            double t = (i + 0.5) * dt;
            double *p = m->step[k][i].p;
            p[0] = dir[0] * t;
            p[1] = r + dir[1] * t;
            p[2] = dir[2] * t;
            double rp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            m->step[k][i].rp = rp;
            double rs[3], ms, ext[3];
            medium(a, rp - a->ground_radius, rs, &ms, ext);
            for (int c = 0; c < 3; c++) {
                double seg = exp(-(depth[c] + 0.5 * ext[c] * dt));
                double scat = rs[c] + ms;
                m->step[k][i].lit[c] = seg * scat;
                m->f[c] += seg * scat * dt;
                depth[c] += ext[c] * dt;
            }
        }
    }
}

/* psi_ms with the sun at cos-zenith mu_s: the second order of scattering
 * with an isotropic phase, over the traced sphere of directions, divided by
 * (1 - f_ms) for all orders beyond (a geometric series). */
static void ms_sum(const tl_atmosphere *a, const ms_rays *m, double mu_s, transmittance_fn tr,
                   const void *ctx, double out[3])
{
    const double iso = 1.0 / (4.0 * PI);
    double L[3] = {0, 0, 0};
    double sun[3] = {sqrt(fmax(0.0, 1.0 - mu_s * mu_s)), mu_s, 0.0};
    for (int k = 0; k < m->dirs; k++) {
        double dt = m->ray[k].dt;
        for (int i = 0; i < m->steps; i++) {
            const double *p = m->step[k][i].p, rp = m->step[k][i].rp;
            double mu_sp = (p[0] * sun[0] + p[1] * sun[1] + p[2] * sun[2]) / rp, ts[3];
            tr(ctx, rp, mu_sp, ts);
            for (int c = 0; c < 3; c++)
                L[c] += m->step[k][i].lit[c] * ts[c] * iso * dt;
        }
        if (m->ray[k].ground)
            add_ground(a, tr, ctx, m->ray[k].dir, m->r, m->ray[k].dist, sun, m->ray[k].depth, L);
    }
    /* Both are means over the sphere of directions; f is the share of
     * light a scattering event passes on (< 1 in any real atmosphere). */
    for (int c = 0; c < 3; c++)
        out[c] = L[c] / m->dirs / (1.0 - fmin(m->f[c] / m->dirs, 0.999));
}

/* One row of the multiple-scattering table: psi_ms at one height for each
 * sun angle, its rays traced once. */
static void ms_row(void *ctx, int j)
{
    tl_sky_luts *l = ctx;
    const tl_atmosphere *a = &l->atmosphere;
    /* v = sqrt(h / H): rows crowd near the ground, where it changes. */
    double v = (j + 0.5) / TL_SKY_MS_SIZE;
    ms_rays m;
    ms_trace(a, a->ground_radius + v * v * (a->top_radius - a->ground_radius), 64, 20, &m);
    for (int i = 0; i < TL_SKY_MS_SIZE; i++) {
        /* mu_s = x·|x|: columns crowd where the sun sets, where it changes. */
        double x = 2.0 * (i + 0.5) / TL_SKY_MS_SIZE - 1.0, out[3];
        ms_sum(a, &m, x * fabs(x), table_transmittance, l, out);
        for (int c = 0; c < 3; c++)
            l->ms[j][i][c] = (float)out[c];
    }
}

/* ---- radiance along a view ray ---- */

static double phase_rayleigh(double c)
{
    return 3.0 / (16.0 * PI) * (1.0 + c * c);
}

static double phase_mie(double c, double g) /* Cornette-Shanks */
{
    double k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + c * c) / pow(1.0 + g * g - 2.0 * g * c, 1.5);
}

typedef void (*ms_fn)(const void *ctx, double r, double mu_s, double out[3]);

static void direct_ms(const void *ctx, double r, double mu_s, double out[3])
{
    ms_rays m;
    ms_trace(ctx, r, 48, 24, &m);
    ms_sum(ctx, &m, mu_s, direct_transmittance, ctx, out);
}

/* Radiance toward the eye at radius r looking along (elevation, azimuth
 * from the sun), the sun at `sun_elevation`, for a sun of illuminance 1. */
static void radiance(const tl_atmosphere *a, transmittance_fn tr, ms_fn ms_of, const void *ctx,
                     double r, double sun_elevation, double elevation, double azimuth, int steps,
                     double out[3])
{
    double dir[3] = {cos(elevation) * sin(azimuth), sin(elevation), cos(elevation) * cos(azimuth)};
    double sun[3] = {0.0, sin(sun_elevation), cos(sun_elevation)};
    double cos_sun = dir[0] * sun[0] + dir[1] * sun[1] + dir[2] * sun[2];
    double pr = phase_rayleigh(cos_sun), pm = phase_mie(cos_sun, a->mie_g);
    double mu = dir[1];
    double ground = to_ground(a, r, mu);
    double d = ground >= 0.0 ? ground : to_top(a, r, mu);
    double depth[3] = {0, 0, 0}, L[3] = {0, 0, 0};
    double prev = 0.0;
    for (int i = 0; i < steps; i++) {
        /* Denser near the eye, where the air is densest along the ray. */
        double t1 = d * ((i + 1.0) / steps) * ((i + 1.0) / steps), dt = t1 - prev;
        double t = prev + 0.5 * dt;
        prev = t1;
        double p[3] = {dir[0] * t, r + dir[1] * t, dir[2] * t};
        double rp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        double rs[3], msc, ext[3], ts[3], psi[3];
        medium(a, rp - a->ground_radius, rs, &msc, ext);
        double mu_s = (p[0] * sun[0] + p[1] * sun[1] + p[2] * sun[2]) / rp;
        tr(ctx, rp, mu_s, ts);
        ms_of(ctx, rp, mu_s, psi);
        for (int c = 0; c < 3; c++) {
            double source = (rs[c] * pr + msc * pm) * ts[c] + (rs[c] + msc) * psi[c];
            double seg = exp(-(depth[c] + 0.5 * ext[c] * dt));
            L[c] += seg * source * dt;
            depth[c] += ext[c] * dt;
        }
    }
    if (ground >= 0.0)
        add_ground(a, tr, ctx, dir, r, d, sun, depth, L);
    for (int c = 0; c < 3; c++)
        out[c] = L[c];
}

/* The sky-view table's latitude mapping: dense at the horizon. */
static double view_latitude(double v)
{
    double l = 2.0 * v - 1.0;
    return (l < 0.0 ? -1.0 : 1.0) * l * l * 0.5 * PI;
}

static double view_v(double latitude)
{
    double l = sqrt(fabs(latitude) / (0.5 * PI));
    return 0.5 + 0.5 * (latitude < 0.0 ? -l : l);
}

static double camera_radius(const tl_atmosphere *a, double altitude)
{
    return a->ground_radius + fmin(fmax(altitude, 1.0), a->top_radius - a->ground_radius - 1.0);
}

/* One step of a sky-view row's rays: what is the same for every ray of
 * the row. The row's rays share their elevation, so they pass the same
 * heights at the same distances: the air there, the optical depth from
 * the eye, and the lookups' coordinates that depend on the height alone.
 * Only the sun's angle to each point differs with the azimuth. */
typedef struct view_step {
    double rp;             /* radius of the step's midpoint */
    double dt;             /* the step's length */
    double rs[3], msc;     /* Rayleigh and Mie scattering there */
    double seg[3];         /* transmittance from the eye to the midpoint */
    double sun_a, sun_b;   /* p·sun = sun_a + sun_b·cos(azimuth) */
    double t_dmin, t_span; /* transmittance_uv's mapping at rp */
    lut_row t_row;         /* and its row there */
    lut_row ms_row;        /* the multiple-scattering table's row at rp (build_ms's v) */
} view_step;

#define VIEW_STEPS 40

/* The sky-view table's row j: radiance() for each azimuth, with what the
 * row's rays share computed once. The renderer builds the same table on the
 * GPU (shaders/sky_view.frag); this is its reference. */
static void build_view_row(tl_sky_luts *l, double r, double sun_elevation, int j)
{
    const tl_atmosphere *a = &l->atmosphere;
    const double lat = view_latitude((j + 0.5) / TL_SKY_VIEW_H);
    const double mu = sin(lat), cos_lat = cos(lat);
    const double sin_s = sin(sun_elevation), cos_s = cos(sun_elevation);
    const double ground = to_ground(a, r, mu);
    const double d = ground >= 0.0 ? ground : to_top(a, r, mu);
    const double H = sqrt(a->top_radius * a->top_radius - a->ground_radius * a->ground_radius);
    view_step st[VIEW_STEPS];
    double depth[3] = {0, 0, 0}, prev = 0.0;
    for (int i = 0; i < VIEW_STEPS; i++) {
        /* Denser near the eye, where the air is densest along the ray. */
        double x = (i + 1.0) / VIEW_STEPS, t1 = d * x * x, dt = t1 - prev;
        double t = prev + 0.5 * dt;
        prev = t1;
        view_step *k = &st[i];
        double along = r + mu * t, flat = cos_lat * t;
        k->rp = sqrt(flat * flat + along * along);
        k->dt = dt;
        double ext[3];
        medium(a, k->rp - a->ground_radius, k->rs, &k->msc, ext);
        for (int c = 0; c < 3; c++) {
            k->seg[c] = exp(-(depth[c] + 0.5 * ext[c] * dt));
            depth[c] += ext[c] * dt;
        }
        k->sun_a = along * sin_s;
        k->sun_b = flat * cos_s;
        double rho = sqrt(fmax(k->rp * k->rp - a->ground_radius * a->ground_radius, 0.0));
        k->t_dmin = a->top_radius - k->rp;
        k->t_span = rho + H - k->t_dmin;
        k->t_row = lut_row_at(TL_SKY_TRANSMITTANCE_H, rho / H);
        k->ms_row = lut_row_at(TL_SKY_MS_SIZE, sqrt(fmax(k->rp - a->ground_radius, 0.0) /
                                                    (a->top_radius - a->ground_radius)));
    }
    const double top2 = a->top_radius * a->top_radius,
                 ground2 = a->ground_radius * a->ground_radius;
    for (int i = 0; i < TL_SKY_VIEW_W; i++) {
        double az = PI * (i + 0.5) / TL_SKY_VIEW_W, cos_az = cos(az);
        double dir[3] = {cos_lat * sin(az), mu, cos_lat * cos_az};
        double sun[3] = {0.0, sin_s, cos_s};
        double cos_sun = mu * sin_s + cos_lat * cos_az * cos_s;
        double pr = phase_rayleigh(cos_sun), pm = phase_mie(cos_sun, a->mie_g);
        double L[3] = {0, 0, 0};
        for (int n = 0; n < VIEW_STEPS; n++) {
            const view_step *k = &st[n];
            double mu_s = (k->sun_a + k->sun_b * cos_az) / k->rp;
            double ts[3] = {0, 0, 0}, psi[3];
            /* lut_transmittance: none where the sun is behind the planet;
             * then its table at transmittance_uv's u */
            double r2 = k->rp * k->rp;
            if (!(mu_s < 0.0 && r2 * (mu_s * mu_s - 1.0) + ground2 >= 0.0)) {
                double to =
                    fmax(0.0, -k->rp * mu_s + sqrt(fmax(r2 * (mu_s * mu_s - 1.0) + top2, 0.0)));
                double u = k->t_span > 0.0 ? (to - k->t_dmin) / k->t_span : 0.0;
                bilinear_row(&l->transmittance[0][0][0], TL_SKY_TRANSMITTANCE_W, &k->t_row, u, ts);
            }
            /* the multiple-scattering table at build_ms's u */
            double mu_u = 0.5 + 0.5 * (mu_s < 0.0 ? -sqrt(-mu_s) : sqrt(mu_s));
            bilinear_row(&l->ms[0][0][0], TL_SKY_MS_SIZE, &k->ms_row, mu_u, psi);
            for (int c = 0; c < 3; c++) {
                double source =
                    (k->rs[c] * pr + k->msc * pm) * ts[c] + (k->rs[c] + k->msc) * psi[c];
                L[c] += k->seg[c] * source * k->dt;
            }
        }
        if (ground >= 0.0)
            add_ground(a, table_transmittance, l, dir, r, d, sun, depth, L);
        for (int c = 0; c < 3; c++)
            l->view[j][i][c] = (float)L[c];
    }
}

/* A sky-view build on the CPU: rows over the cores. */
typedef struct view_build {
    tl_sky_luts *l;
    double r, sun_elevation;
} view_build;

static void view_row(void *ctx, int j)
{
    view_build *b = ctx;
    build_view_row(b->l, b->r, b->sun_elevation, j);
}

double tl_sky_camera_height(const tl_atmosphere *a, double altitude)
{
    return camera_radius(a, altitude) - a->ground_radius;
}

int tl_sky_luts_update_atmosphere(tl_sky_luts *l, const tl_atmosphere *a)
{
    if (l->valid && memcmp(&l->atmosphere, a, sizeof *a) == 0)
        return 0;
    l->atmosphere = *a;
    parallel_rows(TL_SKY_TRANSMITTANCE_H, transmittance_row, l);
    parallel_rows(TL_SKY_MS_SIZE, ms_row, l); /* reads the transmittance table */
    l->valid = 1;
    l->view_valid = 0;
    return 1;
}

int tl_sky_view_stale(const tl_sky_luts *l, double sun_elevation, double altitude)
{
    return !l->view_valid || l->view_sun_elevation != sun_elevation || l->view_altitude != altitude;
}

void tl_sky_view_built(tl_sky_luts *l, double sun_elevation, double altitude)
{
    /* The radiance a white diffuse surface facing up returns: the sky's
     * irradiance on it over pi, the mean of the upper hemisphere weighted
     * by projected solid angle. A row above the horizon spans
     * cos(lat) d(lat) d(azimuth) of solid angle, sin(lat) of it projected,
     * and d(lat) = 2 pi l dv in the table's mapping (lat = l^2 pi/2,
     * l = 2v - 1): the rows crowd toward the horizon, and weighting them
     * by cos(lat) alone made the bright, warm horizon count 2-3 times too
     * much (foam in shadow glowed tan, docs/rendering.md). */
    double sum[3] = {0, 0, 0}, weight = 0.0;
    for (int j = 0; j < TL_SKY_VIEW_H; j++) {
        double v = (j + 0.5) / TL_SKY_VIEW_H, lat = view_latitude(v);
        if (!(lat > 0.0))
            continue;
        double w = cos(lat) * sin(lat) * (2.0 * v - 1.0);
        for (int i = 0; i < TL_SKY_VIEW_W; i++)
            for (int c = 0; c < 3; c++)
                sum[c] += w * l->view[j][i][c];
        weight += w * TL_SKY_VIEW_W;
    }
    for (int c = 0; c < 3; c++)
        l->ambient[c] = weight > 0.0 ? sum[c] / weight : 0.0;
    l->view_sun_elevation = sun_elevation;
    l->view_altitude = altitude;
    l->view_valid = 1;
}

void tl_sky_luts_update(tl_sky_luts *l, const tl_atmosphere *a, double sun_elevation,
                        double altitude)
{
    tl_sky_luts_update_atmosphere(l, a);
    if (!tl_sky_view_stale(l, sun_elevation, altitude))
        return;
    view_build b = {l, camera_radius(&l->atmosphere, altitude), sun_elevation};
    parallel_rows(TL_SKY_VIEW_H, view_row, &b);
    tl_sky_view_built(l, sun_elevation, altitude);
}

void tl_sky_view_lookup(const tl_sky_luts *l, double elevation, double azimuth, double out[3])
{
    double az = fabs(remainder(azimuth, 2.0 * PI)); /* symmetric about the sun's plane */
    bilinear(&l->view[0][0][0], TL_SKY_VIEW_W, TL_SKY_VIEW_H, az / PI, view_v(elevation), out);
}

void tl_sky_reference(const tl_atmosphere *a, double sun_elevation, double altitude,
                      double elevation, double azimuth, double out[3])
{
    radiance(a, direct_transmittance, direct_ms, a, camera_radius(a, altitude), sun_elevation,
             elevation, azimuth, 120, out);
}

void tl_sky_sun_light(const tl_atmosphere *a, double sun_elevation, double altitude,
                      double illuminance, double out[3])
{
    double t[3];
    tl_sky_transmittance(a, camera_radius(a, altitude), sin(sun_elevation), 128, t);
    for (int c = 0; c < 3; c++)
        out[c] = illuminance * t[c];
}
