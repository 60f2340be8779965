// Uses an installed Sinew: parse the model named on the command line and print its Report.
#include <sinew/opensim/parser.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer MODEL.osim\n";
    return 1;
  }
  try {
    sinew::OpenSimParser parser;
    auto system = parser.Parse(argv[1]);
    parser.GetReport().Print(std::cout);
    std::cout << "bodies in the system (with ground): " << system->num_bodies() << "\n";
  } catch (const sinew::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
