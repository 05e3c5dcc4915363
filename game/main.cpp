// qlight: the flythrough demo and the headless renderer (placeholder until the CLI lands).
#include <cstdio>
int main() {
  std::puts("qlight");
  return 0;
}
