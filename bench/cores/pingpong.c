/* How long one core takes to see a write of another: two threads, pinned
 * to two processors, pass a counter back and forth through one cache line
 * (each waits for the other's value, then writes the next). Half the time
 * of a round trip is the one-way latency of a cache line between the two
 * cores.
 *   pingpong A B [ROUND_TRIPS]    (processors A and B, different;
 *                                  default 2,000,000 round trips)
 * Prints "cores A B: one-way N ns"; exits 2 on a bad argument or a
 * processor it may not run on. Built and run by bench/cores.sh. */
#define _GNU_SOURCE
#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* the counter, alone in its cache line */
static struct { _Atomic long value; char pad[64 - sizeof(long)]; } line __attribute__((aligned(64)));
static long trips = 2000000;
static int cpu_b;

static int pin(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

/* a whole number from lo up, or exit 2 naming what it was for */
static long number(const char *s, long lo, const char *what) {
  char *end;
  errno = 0;
  long v = strtol(s, &end, 10);
  if (errno != 0 || end == s || *end != '\0' || v < lo) {
    fprintf(stderr, "pingpong: %s must be a whole number from %ld, got '%s'\n", what, lo, s);
    exit(2);
  }
  return v;
}

/* the second thread: answers every odd value with the next even one */
static void *answer(void *unused) {
  (void)unused;
  if (pin(cpu_b) != 0) { fprintf(stderr, "pingpong: cannot run on processor %d\n", cpu_b); exit(2); }
  for (long i = 0; i < trips; i++) {
    while (atomic_load_explicit(&line.value, memory_order_acquire) != 2 * i + 1) {}
    atomic_store_explicit(&line.value, 2 * i + 2, memory_order_release);
  }
  return NULL;
}

int main(int argc, char **argv) {
  if (argc < 3 || argc > 4) { fprintf(stderr, "usage: pingpong A B [ROUND_TRIPS]\n"); return 2; }
  int cpu_a = (int)number(argv[1], 0, "processor A");
  cpu_b = (int)number(argv[2], 0, "processor B");
  if (argc > 3) trips = number(argv[3], 1, "the number of round trips");
  if (cpu_a == cpu_b) { fprintf(stderr, "pingpong: processors A and B must differ\n"); return 2; }
  if (pin(cpu_a) != 0) { fprintf(stderr, "pingpong: cannot run on processor %d\n", cpu_a); return 2; }
  pthread_t t;
  if (pthread_create(&t, NULL, answer, NULL) != 0) { fprintf(stderr, "pingpong: cannot start a thread\n"); return 2; }
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (long i = 0; i < trips; i++) {
    atomic_store_explicit(&line.value, 2 * i + 1, memory_order_release);
    while (atomic_load_explicit(&line.value, memory_order_acquire) != 2 * i + 2) {}
  }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  pthread_join(t, NULL);
  double ns = (t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec);
  printf("cores %d %d: one-way %.0f ns\n", cpu_a, cpu_b, ns / trips / 2);
  return 0;
}
