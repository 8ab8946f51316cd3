// Holds my_collide (my_collide.hpp) to every property of
// collide_cylinder_sphere; failing cases are saved, drawn and replayable:
//   verify_my_collide [--cases N] [--seed N] [--out DIR] [--replay FILE]
#include "my_collide.hpp"

int main(int argc, char** argv) { return geomcheck::verify(my_subject(), argc, argv); }
