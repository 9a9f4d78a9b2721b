// The check is at compile time (no_yaml_check.hpp); compiling and linking is the test.
int main() {
  return 0;
}
