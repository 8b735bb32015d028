// Strips a mesh file (or the built-in genus-2 model) with an installed singlestrip, writes the
// route, and checks the result with the independent verifier.
#include <singlestrip/errors.hpp>
#include <singlestrip/pipeline.hpp>
#include <singlestrip/route.hpp>
#include <singlestrip/verify.hpp>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    using namespace singlestrip;
    const std::string input = argc > 1 ? argv[1] : kBuiltinGenus2;
    try {
        PipelineOptions options;
        options.name = input;
        const PipelineResult r = stripify(read_input(input), options);
        const Route route = strip_route(r.arrays);

        const VerifyReport report = verify(verify_input(r.input, r.arrays, r.indices));

        std::cout << input << ": " << r.arrays.faces.size() << " faces, " << r.indices.size() << " strip indices, route of "
                  << route.points.size() << " points and length " << route.length << ", verify " << (report.ok() ? "OK" : "FAILED") << '\n';
        return report.ok() ? 0 : 1;
    } catch (const Error& e) {
        std::cerr << "consumer: " << e.what() << '\n';
        return 2;
    }
}
