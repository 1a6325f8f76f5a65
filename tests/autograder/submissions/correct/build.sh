# A correct submission that is built: it makes its `simulator`, a wrapper of the reference
# simulator the kit's test names in $FOSSSIM_REFERENCE (a real submission compiles its own).
printf '#!/bin/sh\nexec "$FOSSSIM_REFERENCE" "$@"\n' > simulator
chmod +x simulator
