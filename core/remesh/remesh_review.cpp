#include "remesh/remesh_review.h"

#include <string>

namespace stratamesh {

RemeshReview remeshAndReview(const Model &input, const RemeshParams &params,
                             const RemeshReviewOptions &options, Progress &progress)
{
    RemeshReview review;
    // Shares measured on modelA5 at 5000 sites: the comparison takes a few % of the remesh.
    const double compareFrom = options.checkInput ? 0.9 : 0.94;
    const double inputFrom = options.checkInput ? 0.97 : 1.0;
    {
        // Unnamed: its stages ("Mesh building: …") read under the caller's title.
        Progress remeshing(progress, 0.0, compareFrom);
        review.result = remeshModel(input, params, remeshing);
    }
    {
        Progress comparing(progress, compareFrom, inputFrom, "Comparing with the input");
        HausdorffParams hausdorff;
        hausdorff.samplesPerSide = kRemeshHausdorffSamples;
        review.comparison = compareModels(input, review.result.model, hausdorff, comparing);
    }
    ComparisonRow &out = review.comparison.output;
    out.resolution = std::to_string(review.result.siteCount);
    out.samplingSeconds = review.result.timings.samplingSeconds;
    out.meshSeconds = review.result.timings.meshSeconds;
    if (options.checkInput) {
        Progress checking(progress, inputFrom, 1.0, "Input validity");
        review.inputValidity = checkValidity(input, checking);
    }
    progress.tick(1.0);
    return review;
}

} // namespace stratamesh
