#include "semantics/optimiser/mpi_evaluation.hpp"

#include <cstdlib>
#include <vector>

#include <mpi.h>
#include <nlohmann/json.hpp>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

enum Tag : int { kWork = 1, kResult = 2, kStop = 3 };

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

// The next message for this rank (from `from`, or any rank), its text, sender and tag.
std::string receive_text(int from, int& source, int& tag) {
  MPI_Status status;
  MPI_Probe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  source = status.MPI_SOURCE;
  tag = status.MPI_TAG;
  return text;
}

}  // namespace

bool launched_by_mpi() {
  // Open MPI's mpirun, MPICH / Slurm's PMI.
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(variable)) return true;
  return false;
}

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void MpiSession::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);  // MPI_Abort does not return; for the compiler
}

EvaluateBatch mpi_evaluate_batch(int size) {
  return [size](const std::vector<Genome>& genomes) {
    std::vector<GenomeEvaluation> out(genomes.size());
    std::size_t next = 0, pending = 0;
    // A work message: "INDEX GENOME".
    const auto hand_out = [&](int worker) {
      send_text(std::to_string(next) + " " + genomes[next].to_string(), worker, kWork);
      ++next;
      ++pending;
    };
    for (int worker = 1; worker < size && next < genomes.size(); ++worker) hand_out(worker);
    while (pending > 0) {
      int source = 0, tag = 0;
      const std::string text = receive_text(MPI_ANY_SOURCE, source, tag);
      if (tag != kResult) throw Error("optimise (MPI): rank " + std::to_string(source) + " sent an unexpected message");
      const nlohmann::json result = nlohmann::json::parse(text);
      out.at(result.at("index").get<std::size_t>()) = evaluation_from_json(result.at("evaluation"));
      --pending;
      if (next < genomes.size()) hand_out(source);
    }
    return out;
  };
}

void stop_mpi_workers(int size) {
  for (int worker = 1; worker < size; ++worker) send_text("", worker, kStop);
}

void serve_mpi_evaluations(const FitnessEvaluator& evaluator) {
  for (;;) {
    int source = 0, tag = 0;
    const std::string text = receive_text(0, source, tag);
    if (tag == kStop) return;
    const auto space = text.find(' ');
    const std::size_t index = std::stoul(text.substr(0, space));
    const Genome genome = Genome::parse(text.substr(space + 1), "MPI work message");
    const nlohmann::json result{{"index", index}, {"evaluation", to_json(evaluator.evaluate(genome))}};
    send_text(result.dump(), 0, kResult);
  }
}

}  // namespace facadeslam::semantics
