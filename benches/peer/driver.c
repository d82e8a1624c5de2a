/* Peer driver for rollbem's benchmark (benches/peer/run.sh): read an LCP file with Siconos numerics' own reader
 * (linearComplementarity_newFromFilename), then run every LCP solver of Siconos numerics 4.4 on it, each in a
 * forked child with a time limit, and report per solver: status, Siconos' info, iterations, Siconos' residual of
 * the answer (lcp_compute_error: ||z - max(0, z - w)||_2 / ||q||_2 with w = M z + q recomputed from z), the
 * median wall time of the solver call alone (clock_gettime around the call; reading the file happens once, in the
 * parent, before any child is forked), z (ZPREFIX.NAME.z) and w = M z + q (ZPREFIX.NAME.w).
 *
 * Usage: driver FILE ZPREFIX
 *   environment (all optional):
 *     TOL=1e-10         tolerance on lcp_compute_error, given to every solver that takes one; "solved" means
 *                       lcp_compute_error of the returned z <= TOL, whatever the solver's own info says
 *     REPEATS=3         timed runs per solver (median reported); a solver whose first run does not reach TOL is
 *                       not repeated, nor is one whose next run might not fit in the time limit (1.5 times
 *                       its longest run so far)
 *     TIME_LIMIT=300    seconds per solver (all its runs): the child is killed by SIGALRM past it
 *     ITER_CAP=10000    iteration cap of the iterative solvers (sweeps of PGS, PSOR, RPGS, CPG, Latin, PG)
 *     NEWTON_MAX_ITER=1000  iteration cap of the semi-smooth Newton methods
 *     PIVOT_MAX_ITER    pivot cap of the pivoting methods (default 50 n + 100)
 *     SOLVERS="a b"     run only these (names below); the others are reported as "skipped"
 *   prints `NAME_key value` lines on stdout, in the order of the solver table, then `solvers NAME NAME ...`.
 *
 * The LCP solvers of Siconos numerics 4.4 (lcp_cst.h, enum LCP_SOLVER, ids 200-222) and what this driver does with
 * each (read from the 4.4.0 source):
 *   lemke (lcp_lexicolemke)        lexicographic Lemke on a dense tableau; run
 *   pgs, psor                      projected Gauss-Seidel / SOR: divide by M_ii; run (with zero diagonal entries
 *                                  they return at once with info 2 and z untouched: reported as failing)
 *   rpgs                           regularized PGS (M_ii + rho): handles zero diagonals; run
 *   cpg                            conjugate projected gradient (a QP method: symmetric M); run
 *   latin, latin_w                 LArge Time INcrement: Cholesky of a matrix built from diag(M); run
 *   newton_min, newton_fb, newton_minfb  semi-smooth Newton (min, Fischer-Burmeister, min + FB line search) with a
 *                                  dense LAPACK solve (DGESV / NM_gesv) per iteration; run
 *   avi_caoferris                  the LCP as an AVI, Cao-Ferris pivoting; run
 *   pivot, bard, murty, pathsearch, pivot_lumod  pivoting methods of lcp_pivot.c / lcp_pivot_lumod.c (Lemke's rule,
 *                                  Bard's, Murty's least index, the pathsearch solver "for testing only",
 *                                  Lemke's rule with block-LU updates); run
 *   convexqp_pg                    projected gradient on min 1/2 z'Mz + q'z, z >= 0 (symmetric M only); run
 *   path, qp, nsqp, gams           need libraries the Debian build does not have (PATH, ql0001, GAMS:
 *                                  SiconosConfig.h leaves HAVE_PATHFERRIS, HAVE_QL0001, HAVE_GAMS_C_API undefined);
 *                                  run anyway: they return at once (path, info 1) or abort (qp, nsqp, gams) and are
 *                                  reported as failing
 *   enum                           enumeration of the 2^n complementary bases: not run for n > ENUM_MAX_N (20)
 *   nsgs_sbm                       block Gauss-Seidel on a sparse-block M (lcp_driver sends a dense M elsewhere):
 *                                  not run (the file's M is dense)
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "LCP_Solvers.h"
#include "LinearComplementarityProblem.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "lcp_cst.h"

#define ENUM_MAX_N 20

typedef void (*lcp_fn)(LinearComplementarityProblem *, double *, double *, int *, SolverOptions *);

enum kind { DIRECT, ITERATIVE, NEWTON };

struct solver
{
  const char *name;
  int id;
  lcp_fn fn;
  enum kind kind;
  int pivot_type; /* for lcp_pivot: 0 = its default (Lemke) */
};

static const struct solver SOLVERS[] = {
  {"lemke", SICONOS_LCP_LEMKE, lcp_lexicolemke, DIRECT, 0},
  {"pivot", SICONOS_LCP_PIVOT, lcp_pivot, DIRECT, 0},
  {"pivot_lumod", SICONOS_LCP_PIVOT_LUMOD, lcp_pivot_lumod, DIRECT, 0},
  {"bard", SICONOS_LCP_BARD, lcp_pivot, DIRECT, SICONOS_LCP_PIVOT_BARD},
  {"murty", SICONOS_LCP_MURTY, lcp_pivot, DIRECT, SICONOS_LCP_PIVOT_LEAST_INDEX},
  {"pathsearch", SICONOS_LCP_PATHSEARCH, lcp_pathsearch, DIRECT, 0},
  {"avi_caoferris", SICONOS_LCP_AVI_CAOFERRIS, lcp_avi_caoferris, DIRECT, 0},
  {"enum", SICONOS_LCP_ENUM, lcp_enum, DIRECT, 0},
  {"newton_min", SICONOS_LCP_NEWTONMIN, lcp_newton_min, NEWTON, 0},
  {"newton_fb", SICONOS_LCP_NEWTON_FB_FBLSA, lcp_newton_FB, NEWTON, 0},
  {"newton_minfb", SICONOS_LCP_NEWTON_MIN_FBLSA, lcp_newton_minFB, NEWTON, 0},
  {"pgs", SICONOS_LCP_PGS, lcp_pgs, ITERATIVE, 0},
  {"psor", SICONOS_LCP_PSOR, lcp_psor, ITERATIVE, 0},
  {"rpgs", SICONOS_LCP_RPGS, lcp_rpgs, ITERATIVE, 0},
  {"cpg", SICONOS_LCP_CPG, lcp_cpg, ITERATIVE, 0},
  {"latin", SICONOS_LCP_LATIN, lcp_latin, ITERATIVE, 0},
  {"latin_w", SICONOS_LCP_LATIN_W, lcp_latin_w, ITERATIVE, 0},
  {"convexqp_pg", SICONOS_LCP_CONVEXQP_PG, lcp_ConvexQP_ProjectedGradient, ITERATIVE, 0},
  {"nsgs_sbm", SICONOS_LCP_NSGS_SBM, lcp_nsgs_SBM, ITERATIVE, 0},
  {"path", SICONOS_LCP_PATH, lcp_path, DIRECT, 0},
  {"qp", SICONOS_LCP_QP, lcp_qp, DIRECT, 0},
  {"nsqp", SICONOS_LCP_NSQP, lcp_nsqp, DIRECT, 0},
  {"gams", SICONOS_LCP_GAMS, lcp_gams, DIRECT, 0},
};
#define NSOLVERS (sizeof SOLVERS / sizeof SOLVERS[0])

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

static double env_double(const char *name, double dflt)
{
  const char *s = getenv(name);
  return (s && *s) ? atof(s) : dflt;
}

static void write_vec(const char *prefix, const char *solver, const char *what, const double *z, int n)
{
  char path[4096];
  snprintf(path, sizeof path, "%s.%s.%s", prefix, solver, what);
  FILE *f = fopen(path, "w");
  if (!f)
  {
    fprintf(stderr, "driver: cannot write %s\n", path);
    _exit(3);
  }
  for (int i = 0; i < n; i++)
    fprintf(f, "%.17g\n", z[i]);
  fclose(f);
}

static int selected(const char *name)
{
  const char *list = getenv("SOLVERS");
  if (!list || !*list)
    return 1;
  size_t len = strlen(name);
  for (const char *p = list; (p = strstr(p, name)); p += len)
    if ((p == list || p[-1] == ' ' || p[-1] == ',') && (p[len] == 0 || p[len] == ' ' || p[len] == ','))
      return 1;
  return 0;
}

/* The child: run one solver up to REPEATS times and write `key value` lines to fd. */
static void run_child(const struct solver *s, LinearComplementarityProblem *lcp, const char *prefix, int fd)
{
  int n = lcp->size;
  double tol = env_double("TOL", 1e-10);
  int repeats = (int)env_double("REPEATS", 3);
  double limit = env_double("TIME_LIMIT", 300);
  int iter_cap = (int)env_double("ITER_CAP", 10000);
  int newton_cap = (int)env_double("NEWTON_MAX_ITER", 1000);
  int pivot_cap = (int)env_double("PIVOT_MAX_ITER", 50.0 * n + 100);
  FILE *out = fdopen(fd, "w");
  if (repeats < 1 || repeats > 99)
    repeats = 3;

  SolverOptions *opt = solver_options_create(s->id);
  switch (s->kind)
  {
  case DIRECT:
    opt->iparam[SICONOS_IPARAM_MAX_ITER] = pivot_cap;
    break; /* the pivoting methods' dparam[TOL] is a pivot tolerance: left at Siconos' default */
  case NEWTON:
    opt->iparam[SICONOS_IPARAM_MAX_ITER] = newton_cap;
    opt->dparam[SICONOS_DPARAM_TOL] = tol;
    break;
  case ITERATIVE:
    opt->iparam[SICONOS_IPARAM_MAX_ITER] = iter_cap;
    opt->dparam[SICONOS_DPARAM_TOL] = tol;
    break;
  }
  if (s->pivot_type)
    opt->iparam[SICONOS_LCP_IPARAM_PIVOTING_METHOD_TYPE] = s->pivot_type;
  if (s->id == SICONOS_LCP_PATH || s->id == SICONOS_LCP_AVI_CAOFERRIS)
    opt->dparam[SICONOS_DPARAM_TOL] = tol;
  fprintf(out, "%s_max_iterations %d\n", s->name, opt->iparam[SICONOS_IPARAM_MAX_ITER]);
  fprintf(out, "%s_solver_tolerance %.3e\n", s->name, opt->dparam[SICONOS_DPARAM_TOL]);
  fflush(out);

  double *z = calloc((size_t)n, sizeof(double));
  double *w = calloc((size_t)n, sizeof(double));
  double times[99];
  int info = -1, runs = 0;
  double error = NAN, started = now();
  alarm((unsigned)ceil(limit));
  for (int r = 0; r < repeats; r++)
  {
    memset(z, 0, (size_t)n * sizeof(double));
    memset(w, 0, (size_t)n * sizeof(double));
    opt->iparam[SICONOS_IPARAM_ITER_DONE] = 0;
    info = -1;
    double t0 = now();
    s->fn(lcp, z, w, &info, opt);
    times[r] = now() - t0;
    runs++;
    fprintf(out, "%s_run_time_s %.6e\n", s->name, times[r]);
    fflush(out);
    if (r == 0)
    {
      lcp_compute_error(lcp, z, w, tol, &error);
      if (!(error <= tol))
        break; /* not solved: one run says so */
    }
    /* Another run only if it fits with a margin (runs vary by tens of percent on a loaded machine): a child
       killed by the alarm loses its completed runs. */
    double longest = 0.0;
    for (int k = 0; k <= r; k++)
      longest = fmax(longest, times[k]);
    if (now() - started + 1.5 * longest > 0.95 * limit)
      break;
  }
  alarm(0);
  lcp_compute_error(lcp, z, w, tol, &error);
  int finite = 1;
  for (int i = 0; i < n; i++)
    finite &= isfinite(z[i]);
  fprintf(out, "%s_status %s\n", s->name, error <= tol ? "solved" : "failed");
  fprintf(out, "%s_info %d\n", s->name, info);
  fprintf(out, "%s_iterations %d\n", s->name, opt->iparam[SICONOS_IPARAM_ITER_DONE]);
  fprintf(out, "%s_error %.3e\n", s->name, error);
  fprintf(out, "%s_runs %d\n", s->name, runs);
  fprintf(out, "%s_time_s %.6e\n", s->name, median(times, runs));
  if (finite)
  {
    write_vec(prefix, s->name, "z", z, n);
    write_vec(prefix, s->name, "w", w, n); /* w = M z + q, recomputed by lcp_compute_error */
  }
  fclose(out);
  _exit(0);
}

/* Parent: fork, collect the child's lines, report how it ended. */
static void run_solver(const struct solver *s, LinearComplementarityProblem *lcp, const char *prefix)
{
  int n = lcp->size;
  if (!selected(s->name))
  {
    printf("%s_status skipped\n", s->name);
    return;
  }
  if (s->id == SICONOS_LCP_ENUM && n > ENUM_MAX_N)
  {
    printf("%s_status not_applicable\n%s_reason enumerates up to 2^n complementary bases (n = %d)\n", s->name,
           s->name, n);
    return;
  }
  if (s->id == SICONOS_LCP_NSGS_SBM && lcp->M->storageType != NM_SPARSE_BLOCK)
  {
    printf("%s_status not_applicable\n%s_reason needs a sparse-block M (the file's M is dense)\n", s->name,
           s->name);
    return;
  }
  int fds[2];
  if (pipe(fds))
  {
    perror("pipe");
    exit(3);
  }
  fflush(stdout);
  fflush(stderr);
  double t0 = now();
  pid_t pid = fork();
  if (pid < 0)
  {
    perror("fork");
    exit(3);
  }
  if (pid == 0)
  {
    close(fds[0]);
    /* Siconos' solvers print to stdout: keep them off the key-value stream. */
    dup2(STDERR_FILENO, STDOUT_FILENO);
    run_child(s, lcp, prefix, fds[1]);
  }
  close(fds[1]);
  /* Copy the child's lines; remember whether it reached its status line. */
  FILE *in = fdopen(fds[0], "r");
  char line[1024], key[256];
  int has_status = 0, runs = 0;
  snprintf(key, sizeof key, "%s_status ", s->name);
  while (fgets(line, sizeof line, in))
  {
    fputs(line, stdout);
    if (!strncmp(line, key, strlen(key)))
      has_status = 1;
    if (strstr(line, "_run_time_s "))
      runs++;
  }
  fclose(in);
  int st = 0;
  while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
    ;
  double elapsed = now() - t0;
  if (!has_status)
  {
    if (WIFSIGNALED(st) && WTERMSIG(st) == SIGALRM)
      printf("%s_status time_limit\n%s_reason over the time limit of %g s (%d run(s) completed)\n", s->name, s->name,
             env_double("TIME_LIMIT", 300), runs);
    else if (WIFSIGNALED(st))
      printf("%s_status crashed\n%s_reason killed by signal %d (%s) after %.3g s\n", s->name, s->name,
             WTERMSIG(st), strsignal(WTERMSIG(st)), elapsed);
    else
      printf("%s_status crashed\n%s_reason exited with code %d after %.3g s (see stderr: Siconos' message)\n",
             s->name, s->name, WEXITSTATUS(st), elapsed);
  }
  fflush(stdout);
}

int main(int argc, char **argv)
{
  if (argc != 3)
  {
    fprintf(stderr, "usage: %s FILE ZPREFIX (settings in the environment: see the source)\n", argv[0]);
    return 2;
  }
  const char *file = argv[1];
  const char *prefix = argv[2];

  double t0 = now();
  LinearComplementarityProblem *lcp = newLCP();
  linearComplementarity_newFromFilename(lcp, file);
  int n = lcp->size;
  if (n <= 0 || !lcp->M || lcp->M->size0 != n || lcp->M->size1 != n)
  {
    fprintf(stderr, "driver: %s is not an n x n LCP\n", file);
    return 2;
  }
  printf("n %d\n", n);
  printf("storage %d\n", lcp->M->storageType);
  printf("read_time_s %.3f\n", now() - t0);
  int zero_diag = 0;
  for (int i = 0; i < n; i++)
    if (fabs(NM_get_value(lcp->M, i, i)) < DBL_EPSILON)
      zero_diag++;
  printf("zero_diagonal_entries %d\n", zero_diag);
  printf("tolerance %.3e\n", env_double("TOL", 1e-10));
  printf("time_limit_s %g\n", env_double("TIME_LIMIT", 300));
  fflush(stdout);

  printf("solvers");
  for (size_t k = 0; k < NSOLVERS; k++)
    printf(" %s", SOLVERS[k].name);
  printf("\n");
  for (size_t k = 0; k < NSOLVERS; k++)
  {
    fprintf(stderr, "[driver] n = %d: %s\n", n, SOLVERS[k].name);
    run_solver(&SOLVERS[k], lcp, prefix);
  }
  freeLinearComplementarityProblem(lcp);
  return 0;
}
