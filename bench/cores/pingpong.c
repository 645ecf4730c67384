/* How long one core takes to see a write of another: two threads, pinned
 * to two processors, pass a counter back and forth through one cache line
 * (each waits for the other's value, then writes the next); the time per
 * pass is the one-way latency of a cache line between the two cores.
 *   pingpong A B [PASSES]    (processors A and B; default 2,000,000 passes)
 * Prints "cores A B: one-way N ns". Built and run by bench/cores.sh. */
#define _GNU_SOURCE
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static _Atomic long line __attribute__((aligned(64)));
static long passes = 2000000;
static int cpu_b;

static int pin(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

/* the second thread: answers every odd value with the next even one */
static void *answer(void *unused) {
  (void)unused;
  if (pin(cpu_b) != 0) { fprintf(stderr, "pingpong: cannot run on processor %d\n", cpu_b); exit(2); }
  for (long i = 0; i < passes; i++) {
    while (atomic_load_explicit(&line, memory_order_acquire) != 2 * i + 1) {}
    atomic_store_explicit(&line, 2 * i + 2, memory_order_release);
  }
  return NULL;
}

int main(int argc, char **argv) {
  if (argc < 3) { fprintf(stderr, "usage: pingpong A B [PASSES]\n"); return 2; }
  int cpu_a = atoi(argv[1]);
  cpu_b = atoi(argv[2]);
  if (argc > 3) passes = atol(argv[3]);
  if (pin(cpu_a) != 0) { fprintf(stderr, "pingpong: cannot run on processor %d\n", cpu_a); return 2; }
  pthread_t t;
  pthread_create(&t, NULL, answer, NULL);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (long i = 0; i < passes; i++) {
    atomic_store_explicit(&line, 2 * i + 1, memory_order_release);
    while (atomic_load_explicit(&line, memory_order_acquire) != 2 * i + 2) {}
  }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  pthread_join(t, NULL);
  double ns = (t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec);
  printf("cores %d %d: one-way %.0f ns\n", cpu_a, cpu_b, ns / passes / 2);
  return 0;
}
