// The batch progress bar on stderr (app layer): "\r[#####.....] 3/10 (1 failed)  name", drawn
// only when stderr is a terminal, the line ended once the last file is done.
#pragma once

#include "app/batch.hpp"

namespace singlestrip::app {

class ProgressBar {
public:
    ProgressBar();  ///< checks whether stderr is a terminal
    /// The callback for run_batch_files(); does nothing when stderr is not a terminal.
    [[nodiscard]] BatchProgressFn callback() const;

private:
    bool terminal_ = false;
};

}  // namespace singlestrip::app
