// The Enki side of bench/enki.sh: N e-pucks running a Braitenberg obstacle
// avoider in a square walled arena, at dt = 0.01, timed in CPU seconds.
//
//   enki-swarm ROBOTS COVERAGE SECONDS
//
// The arena's side is chosen so that the robots' discs cover the fraction
// COVERAGE of the floor (an e-puck is 7.4 cm across). The robots start on
// a jittered lattice, clear of each other and of the walls, with the same
// deterministic placement and headings as afrp's bench/Swarm.hs (in
// e-puck units instead of simbot units). Each robot reads its 8 infrared
// sensors (the distance Enki infers from each, 0 to 12 cm), maps them
// linearly to an activation in [0, 1] and the activations linearly to the
// two wheel speeds, with the weights of bench/Swarm.hs.
//
// Prints one line of key=value pairs (read by bench/enki.sh).
//
// Built only by bench/enki.sh (g++ against Debian's libenki-dev); never
// part of the Haskell build.

#include <enki/PhysicalEngine.h>
#include <enki/robots/e-puck/EPuck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

namespace {

const double kRadius = 3.7;      // e-puck radius, cm (EPuck.cpp)
const double kMaxSpeed = 12.8;   // e-puck wheel speed limit, cm/s
const double kReach = 12.0;      // IR range, cm: activation 0 at or beyond it
const double kBase = kMaxSpeed / 2;
const double kDt = 0.01;

// Braitenberg weights, sensors 0..7 = front-front-right, front-right,
// right, back-right, back-left, left, front-left, front-front-left (the
// same numbers as bench/Swarm.hs's wheelWeights).
const double kWeightLeft[8]  = {-1.5, -0.8, -0.3, 0.3, 0.3,  0.3,  0.6, -0.5};
const double kWeightRight[8] = { 1.0,  0.6,  0.3, 0.3, 0.3, -0.3, -0.8, -0.8};

// A small deterministic hash and a number in [0, 1) from it (the same as
// bench/Swarm.hs's).
int64_t hash(int64_t x) {
  int64_t y = (x * 2654435761LL + 12345) % 4294967296LL;
  return (y / 65536) * 31 + y % 65536;
}

double unit(int64_t x) { return static_cast<double>(hash(x) % 10007) / 10007.0; }

double clamp(double v) { return std::max(-kMaxSpeed, std::min(kMaxSpeed, v)); }

class Avoider : public Enki::EPuck {
 public:
  Avoider() : Enki::EPuck(CAPABILITY_BASIC_SENSORS) {}

 protected:
  void controlStep(double dt) override {
    const Enki::IRSensor *ir[8] = {&infraredSensor0, &infraredSensor1, &infraredSensor2,
                                   &infraredSensor3, &infraredSensor4, &infraredSensor5,
                                   &infraredSensor6, &infraredSensor7};
    double l = 1, r = 1;
    for (int i = 0; i < 8; ++i) {
      double d = ir[i]->getDist();
      double a = std::isfinite(d) ? std::max(0.0, std::min(1.0, 1 - d / kReach)) : 0;
      l += kWeightLeft[i] * a;
      r += kWeightRight[i] * a;
    }
    leftSpeed = clamp(kBase * l);
    rightSpeed = clamp(kBase * r);
    Enki::EPuck::controlStep(dt);
  }
};

double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

int main(int argc, char **argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: enki-swarm ROBOTS COVERAGE SECONDS\n");
    return 2;
  }
  const int n = std::atoi(argv[1]);
  const double coverage = std::atof(argv[2]);
  const double seconds = std::atof(argv[3]);
  if (n < 1 || !(coverage > 0 && coverage < 0.5) || !(seconds > 0)) {
    std::fprintf(stderr, "enki-swarm: need ROBOTS >= 1, 0 < COVERAGE < 0.5, SECONDS > 0\n");
    return 2;
  }
  const double diameter = 2 * kRadius;
  const double side = std::sqrt(n * M_PI * kRadius * kRadius / coverage);
  const int k = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double spacing = side / k;
  if (spacing < diameter * 1.05) {
    std::fprintf(stderr, "enki-swarm: the lattice is too tight for %d robots\n", n);
    return 2;
  }
  const double jitter = 0.2 * (spacing - diameter);

  Enki::World world(side, side);
  for (int i = 0; i < n; ++i) {
    const int a = i % k, b = i / k;
    auto *robot = new Avoider;
    robot->pos = Enki::Point((a + 0.5) * spacing + jitter * (2 * unit(a * 3 + b) - 1),
                             (b + 0.5) * spacing + jitter * (2 * unit(a + b * 5) - 1));
    robot->angle = 2 * M_PI * unit(i * 17);
    world.addObject(robot);
  }
  world.setRandomSeed(1);

  const long steps = std::lround(seconds / kDt);
  const double c0 = cpuSeconds();
  for (long s = 0; s < steps; ++s) world.step(kDt, 1);
  const double cpu = cpuSeconds() - c0;

  double checksum = 0;
  for (auto *o : world.objects) checksum += o->pos.x + o->pos.y;
  const double simT = steps * kDt;
  std::printf("engine=enki robots=%d coverage=%.3f side=%.1fcm steps=%ld cpu=%.3f xrt=%.2f"
              " robot_steps_per_s=%.0f checksum=%.6e\n",
              n, coverage, side, steps, cpu, simT / cpu, n * steps / cpu, checksum);
  return 0;
}
