/* Peer driver for rollbem's benchmark (benches/peer/run.sh): read an LCP file in the format of Siconos numerics'
 * LCP test collection with Siconos' own reader (linearComplementarity_newFromFilename), solve it with Siconos'
 * lexicographic Lemke (lcp_lexicolemke) and projected Gauss-Seidel (lcp_pgs), and report, per solver, the solver's
 * status, iterations, Siconos' residual (lcp_compute_error: ||z - max(0, z - w)||_2 / ||q||_2 with w = M z + q
 * recomputed from z) and the median wall time of `repeats` solves (the solve call only: reading the file and the
 * conversion of a sparse-block M to dense happen before the clock starts).
 *
 * Usage: driver FILE ZPREFIX [PGS_TOL [PGS_MAX_ITER [REPEATS [LEMKE_MAX_ITER]]]]
 *   writes ZPREFIX.lemke.z and ZPREFIX.pgs.z (one z_i per line, %.17g) and prints `key value` lines on stdout.
 *   Defaults: PGS_TOL 1e-10, PGS_MAX_ITER 1000, REPEATS 3, LEMKE_MAX_ITER 50 n + 100.
 *
 * Notes on Siconos 4.4 (the Debian bookworm package), read from its source:
 *  - lcp_lexicolemke needs a dense M (it reads M->matrix0), so a sparse-block M is converted first;
 *  - lcp_lexicolemke returns info = 0 also when it stops on a secondary ray (it sets Ifound = 1 when no row
 *    blocks), so `solved` here means info = 0 AND a small residual;
 *  - its iteration count excludes the initial pivot that brings z0 into the basis (rollbem counts it);
 *  - lcp_pgs never sets *info and returns at once, with residual 0, when a diagonal entry of M vanishes, so the
 *    driver checks the diagonal itself and recomputes the residual after the solve.
 */
#define _POSIX_C_SOURCE 199309L
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "LCP_Solvers.h"
#include "LinearComplementarityProblem.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "lcp_cst.h"

/* A solution counts as one when Siconos' relative residual is at most this. */
#define SOLVED_TOL 1e-8

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int k)
{
  qsort(v, (size_t)k, sizeof(double), cmp_double);
  return (k % 2) ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
}

static void write_z(const char *prefix, const char *solver, const double *z, int n)
{
  char path[4096];
  snprintf(path, sizeof path, "%s.%s.z", prefix, solver);
  FILE *f = fopen(path, "w");
  if (!f)
  {
    fprintf(stderr, "driver: cannot write %s\n", path);
    exit(3);
  }
  for (int i = 0; i < n; i++)
    fprintf(f, "%.17g\n", z[i]);
  fclose(f);
}

static double max_abs(const double *v, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++)
    m = fmax(m, fabs(v[i]));
  return m;
}

int main(int argc, char **argv)
{
  if (argc < 3)
  {
    fprintf(stderr, "usage: %s FILE ZPREFIX [PGS_TOL [PGS_MAX_ITER [REPEATS [LEMKE_MAX_ITER]]]]\n", argv[0]);
    return 2;
  }
  const char *file = argv[1];
  const char *prefix = argv[2];
  double pgs_tol = argc > 3 ? atof(argv[3]) : 1e-10;
  int pgs_max_iter = argc > 4 ? atoi(argv[4]) : 1000;
  int repeats = argc > 5 ? atoi(argv[5]) : 3;
  if (repeats < 1 || repeats > 99)
  {
    fprintf(stderr, "driver: REPEATS must be in 1..99\n");
    return 2;
  }

  LinearComplementarityProblem *lcp = newLCP();
  linearComplementarity_newFromFilename(lcp, file);
  int n = lcp->size;
  if (n <= 0 || !lcp->M || lcp->M->size0 != n || lcp->M->size1 != n)
  {
    fprintf(stderr, "driver: %s is not an n x n LCP\n", file);
    return 2;
  }
  int lemke_max_iter = argc > 6 ? atoi(argv[6]) : 50 * n + 100;
  printf("n %d\n", n);
  printf("storage %d\n", lcp->M->storageType);

  /* lcp_lexicolemke reads M->matrix0: hand it a dense copy of a sparse-block M. */
  if (lcp->M->storageType != NM_DENSE)
  {
    NumericsMatrix *dense = NM_create(NM_DENSE, n, n);
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++)
        dense->matrix0[i + j * n] = NM_get_value(lcp->M, i, j);
    NM_clear(lcp->M);
    free(lcp->M);
    lcp->M = dense;
  }

  double *z = calloc((size_t)n, sizeof(double));
  double *w = calloc((size_t)n, sizeof(double));
  double times[99];
  double error = 0.0;

  /* Lexicographic Lemke. */
  {
    SolverOptions *opt = solver_options_create(SICONOS_LCP_LEMKE);
    opt->iparam[SICONOS_IPARAM_MAX_ITER] = lemke_max_iter;
    int info = -1;
    for (int r = 0; r < repeats; r++)
    {
      memset(z, 0, (size_t)n * sizeof(double));
      memset(w, 0, (size_t)n * sizeof(double));
      double t0 = now();
      lcp_lexicolemke(lcp, z, w, &info, opt);
      times[r] = now() - t0;
    }
    int iters = opt->iparam[SICONOS_IPARAM_ITER_DONE];
    lcp_compute_error(lcp, z, w, SOLVED_TOL, &error);
    const char *status = (info == 0 && error <= SOLVED_TOL) ? "solved"
                         : (info == 0)                      ? "failed_ray_or_inaccurate"
                                                            : "not_converged";
    printf("lemke_status %s\n", status);
    printf("lemke_info %d\n", info);
    printf("lemke_iterations %d\n", iters);
    printf("lemke_max_iterations %d\n", lemke_max_iter);
    printf("lemke_error %.3e\n", error);
    printf("lemke_zmax %.17g\n", max_abs(z, n));
    printf("lemke_time_s %.6e\n", median(times, repeats));
    write_z(prefix, "lemke", z, n);
    solver_options_delete(opt);
    free(opt);
  }

  /* Projected Gauss-Seidel. */
  {
    int zero_diag = 0;
    for (int i = 0; i < n; i++)
      if (fabs(lcp->M->matrix0[i + i * n]) < DBL_EPSILON)
        zero_diag++;
    printf("pgs_tolerance %.3e\n", pgs_tol);
    printf("pgs_max_iterations %d\n", pgs_max_iter);
    if (zero_diag)
    {
      /* lcp_pgs divides by M_ii: it returns at once, z untouched. */
      printf("pgs_status zero_diagonal\n");
      printf("pgs_zero_diagonal_entries %d\n", zero_diag);
    }
    else
    {
      SolverOptions *opt = solver_options_create(SICONOS_LCP_PGS);
      opt->iparam[SICONOS_IPARAM_MAX_ITER] = pgs_max_iter;
      opt->dparam[SICONOS_DPARAM_TOL] = pgs_tol;
      int info = -1;
      for (int r = 0; r < repeats; r++)
      {
        memset(z, 0, (size_t)n * sizeof(double));
        memset(w, 0, (size_t)n * sizeof(double));
        double t0 = now();
        lcp_pgs(lcp, z, w, &info, opt);
        times[r] = now() - t0;
      }
      int iters = opt->iparam[SICONOS_IPARAM_ITER_DONE];
      lcp_compute_error(lcp, z, w, pgs_tol, &error);
      printf("pgs_status %s\n", error <= pgs_tol ? "solved" : "not_converged");
      printf("pgs_iterations %d\n", iters);
      printf("pgs_error %.3e\n", error);
      printf("pgs_zmax %.17g\n", max_abs(z, n));
      printf("pgs_time_s %.6e\n", median(times, repeats));
      write_z(prefix, "pgs", z, n);
      solver_options_delete(opt);
      free(opt);
    }
  }

  free(z);
  free(w);
  freeLinearComplementarityProblem(lcp);
  return 0;
}
