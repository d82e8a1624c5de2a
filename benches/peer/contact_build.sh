# Building CONTACT (E. Vollebregt's rolling-contact program, Fortran, Apache-2.0) with gfortran, with or without
# Intel oneMKL, and checking a build against CONTACT's shipped reference outputs. Sourced by contact.sh and
# contact3d.sh (not run on its own); see benches/peer/README.md, "Building CONTACT".
#
# The caller sets, before sourcing:
#   work           the work folder (the build, MKL's wheels and the checks live under it)
#   contact_mkl    1: build with Intel oneMKL from PyPI (FFT products and FFT preconditioners, CONTACT at its best);
#                  0: without MKL (every FFT path compiled out)
# and may set CONTACT_REPO (where CONTACT's sources are cloned from without a tree), CONTACT_COMMIT (the commit
# to name for a tree that is not a git checkout) and MKL_VERSION (the PyPI version of
# mkl-static and mkl-include; default: the newest).
# It defines say/die if the caller has not.
#
# Functions (each documented below):
#   contact_install_tools [EXTRA_PKG...]   Debian packages the build (and the caller) needs, with apt-get
#   contact_get_source SRC                 CONTACT's source tree (given, or cloned): sets contact_src, contact_rev,
#                                          contact_commit
#   contact_get_mkl                        mkl-static + mkl-include wheels from PyPI, unpacked in $work/mkl: sets
#                                          mkl_root, mkl_lib, mkl_inc, mkl_version
#   build_contact DST                      builds bin/contact_linux64 in DST: sets contact_fflags, contact_libs,
#                                          contact_build (one line saying which build it is)
#   contact_ref_check NAME INP_DIR         runs the build on CONTACT's example NAME and compares it with NAME.ref_out
#                                          (refuses, exit 1, beyond the printed digits)

declare -F say >/dev/null || say() { echo "[contact-build] $*" >&2; }
declare -F die >/dev/null || die() {
  echo "[contact-build] error: $*" >&2
  exit 1
}
contact_build_here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# Debian's packages: gfortran and make for CONTACT; python3 for the reference check (contact_refcmp.py); with MKL
# python3-pip (pip download) and unzip (the wheels);
# without MKL reference LAPACK/BLAS (CONTACT's B-spline profile code calls dgbsv/dpbsv, which MKL provides
# otherwise); GNU time and taskset (util-linux) for the timings; git to clone. Extra packages as arguments.
contact_install_tools() {
  local need=() pkg sudo=()
  local pkgs=(gfortran make time util-linux git python3 "$@")
  if ((contact_mkl)); then pkgs+=(python3-pip unzip); else pkgs+=(liblapack-dev libblas-dev); fi
  for pkg in "${pkgs[@]}"; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
  done
  # A pip from elsewhere (pyenv, a venv) serves as well as Debian's.
  if ((contact_mkl)) && [[ " ${need[*]} " == *" python3-pip "* ]] && python3 -m pip --version >/dev/null 2>&1; then
    need=("${need[@]/python3-pip/}")
    read -ra need <<<"${need[*]}"
  fi
  ((${#need[@]})) || return 0
  if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
  say "installing ${need[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq "${need[@]}" >/dev/null
}

# CONTACT's sources: SRC if given, else a shallow clone of $CONTACT_REPO into $work/CONTACT.
contact_get_source() {
  local src=$1 f
  if [[ -z $src ]]; then
    src="$work/CONTACT"
    if [[ ! -d $src/src ]]; then
      say "no CONTACT_SRC given: cloning ${CONTACT_REPO:-https://github.com/eve70a/CONTACT}"
      git clone -q --depth 1 "${CONTACT_REPO:-https://github.com/eve70a/CONTACT}" "$src"
    fi
  fi
  contact_src=$(cd "$src" && pwd)
  for f in src/makefile src/make_inc.linux src/VERSION src/m_aijpj.f90 src/mkl_dfti.f90; do
    [[ -f $contact_src/$f ]] || die "$contact_src is not a CONTACT source tree (no $f)"
  done
  # shellcheck disable=SC2016 # the $ are literal (Subversion keywords)
  contact_rev=$(sed -n 's/.*\$Revision: *\([0-9]*\) *\$, *\$Date:: *\([0-9-]*\).*/r\1 (\2)/p' "$contact_src/src/VERSION" | head -n 1)
  contact_commit=${CONTACT_COMMIT:-$(git -C "$contact_src" rev-parse --short=12 HEAD 2>/dev/null || echo "not a git checkout")}
}

# Intel oneMKL from PyPI, into the work folder only (nothing installed system-wide): `pip download --no-deps` of the
# wheels mkl-static (the static libraries, lib/) and mkl-include (headers and Fortran interface sources,
# include/), unpacked with unzip. A wheel is a zip; its payload sits under NAME-VERSION.data/data/.
contact_get_mkl() {
  local dir="$work/mkl" spec_s=mkl-static spec_i=mkl-include w
  if [[ -n ${MKL_VERSION:-} ]]; then
    spec_s="mkl-static==$MKL_VERSION"
    spec_i="mkl-include==$MKL_VERSION"
  fi
  mkdir -p "$dir/wheels" "$dir/root"
  if ! ls "$dir"/wheels/mkl_static-*.whl >/dev/null 2>&1 || ! ls "$dir"/wheels/mkl_include-*.whl >/dev/null 2>&1; then
    say "downloading Intel oneMKL from PyPI ($spec_s, $spec_i; about 250 MB)"
    python3 -m pip download --no-deps --only-binary=:all: --platform manylinux_2_28_x86_64 -q -d "$dir/wheels" \
      "$spec_s" "$spec_i" >&2 || die "pip download of $spec_s $spec_i failed"
  fi
  if [[ ! -f $dir/root/.unpacked ]]; then
    for w in "$dir"/wheels/mkl_static-*.whl "$dir"/wheels/mkl_include-*.whl; do
      unzip -q -o "$w" -d "$dir/root" || die "could not unpack $w"
    done
    touch "$dir/root/.unpacked"
  fi
  mkl_lib=$(dirname "$(find "$dir/root" -name libmkl_core.a | head -n 1)")
  mkl_inc=$(dirname "$(find "$dir/root" -name mkl_dfti.f90 | head -n 1)")
  [[ -f $mkl_lib/libmkl_gf_lp64.a && -f $mkl_lib/libmkl_sequential.a && -f $mkl_lib/libmkl_core.a ]] ||
    die "no libmkl_gf_lp64.a, libmkl_sequential.a, libmkl_core.a under $dir/root"
  [[ -d $mkl_inc ]] || die "no MKL include folder (mkl_dfti.f90) under $dir/root"
  mkl_root=$dir/root
  mkl_version=$(basename "$(ls "$dir"/wheels/mkl_static-*.whl | head -n 1)" | cut -d- -f2)
}

# Edit FILE with the sed expression EXPR when its line matches WHAT (an ifort-only construct, or a line to change);
# afterwards WHAT must be gone. Upstream fixes make an edit a no-op; a construct that changed shape makes the build
# stop here, loudly.
port_edit() {
  local file=$1 what=$2 expr=$3
  if grep -qE -e "$what" "$file"; then
    sed -i -E "$expr" "$file"
    if grep -qE -e "$what" "$file"; then die "edit of $file did not apply ($what)"; fi
  else
    say "  ($(basename "$file"): no '$what', edit not needed)"
  fi
}

# CONTACT's makefile is written for Intel Fortran with MKL. gfortran builds the stand-alone program (PROD=exe_l64)
# with the variables overridden on make's command line and small edits to a copy of the sources (the user's tree
# is not touched):
#   - FFOPTS: -cpp for ifort's -fpp, -J for ifort's -module, -ffree-line-length-none, -fdec-format-defaults (read
#     formats like '(i)' without a width), -O3 as upstream's FFOPTS_ALL; OPENMP= (one thread);
#   - with MKL: MKLINC='-DWITH_MKLFFT -I<mkl include>' as upstream, MKLLIB the static group for gfortran's calling
#     convention (libmkl_gf_lp64 instead of upstream's ifort libmkl_intel_lp64) with libmkl_sequential and
#     libmkl_core, -lpthread -lm -ldl; CONTACT's own src/mkl_dfti.f90 (compiled by its makefile) is the Fortran
#     interface; two edits in m_aijpj.f90 (below);
#   - without MKL: MKLINC= (no WITH_MKLFFT: every FFT path compiled out), MKLLIB=reference LAPACK/BLAS;
#   - edits where ifort accepts what gfortran does not (each named below).
build_contact() {
  local dst=$1 s arch=() mklinc
  rm -rf "$dst"
  mkdir -p "$dst/bin"
  cp -r "$contact_src/src" "$dst/src"
  s="$dst/src"
  chmod -R u+w "$s"
  rm -rf "$s/obj"
  # m_licensing: a function statement without '()', OPEN(... dispose='delete') and ScanFolder (Intel's ifport,
  # GETFILEINFOQQ; not called by the stand-alone program).
  port_edit "$s/m_licensing.f90" '^function LicenseGetDebug *$' 's/^function LicenseGetDebug *$/function LicenseGetDebug()/'
  port_edit "$s/m_licensing.f90" "dispose='delete'" "s/, *dispose='delete'//"
  sed -i -E "s/^( *)close\(ltmp\)$/\1close(ltmp, status='delete')/" "$s/m_licensing.f90"
  port_edit "$s/m_licensing.f90" '^ *public +ScanFolder' '/^ *public +ScanFolder/d'
  port_edit "$s/m_licensing.f90" 'use ifport' '/^subroutine ScanFolder/,/^end subroutine ScanFolder/d'
  # makefile: ifort's '-assume bscc' (backslash escapes in strings) for m_readline is gfortran's -fbackslash.
  port_edit "$s/makefile" '-assume bscc' 's/-assume bscc/-fbackslash/'
  # m_gridfunc: a private parameter 'strlen' that clashes with the one use-associated from m_globals (same value).
  port_edit "$s/m_gridfunc.f90" '^ *private +strlen *$' '/^ *private +strlen *$/d'
  port_edit "$s/m_gridfunc.f90" '^ *integer, *parameter *:: *strlen *= *16 *$' '/^ *integer, *parameter *:: *strlen *= *16 *$/d'
  # m_bspline_make: .ne. between logicals is .neqv.
  port_edit "$s/m_bspline_make.f90" '\.ne\.mask\(' 's/\.ne\.mask\(/.neqv.mask(/g'
  # m_varprof, m_wr_output: an integer flag (0/1, -1) used as a condition.
  port_edit "$s/m_varprof.f90" 'if \(is_wheel\) then' 's/if \(is_wheel\) then/if (is_wheel.ne.0) then/'
  port_edit "$s/m_wr_output.f90" 'if \(is_right\) then' 's/if \(is_right\) then/if (is_right.ne.0) then/'
  # m_temperature: an ASSOCIATE name used inside the same ASSOCIATE statement.
  port_edit "$s/m_temperature.f90" '=> igs%row(1st|lst)' 's/=> igs%row(1st|lst)/=> outpt%igs%row\1/g'
  if ((contact_mkl)); then
    # m_aijpj (fft_makePrec, fft_VecAijPj): the backward (inverse) FFT descriptor of each routine gets its output
    # strides, the spatial array's layout (0, 1, 2*fft_mx), by uncommenting the author's own line
    # `DftiSetValue(dfti_back, DFTI_OUTPUT_STRIDES, strides_spac)`. Upstream sets only the input strides (the
    # Fourier array's, 0, 1, fft_mx+1) and relies on the output strides defaulting to the spatial layout; with
    # oneMKL 2026.x they do not, the inverse transform writes with the wrong row length, and CONTACT's FFT
    # products and preconditioner come out wrong without an error (carter2d: FX/FSTAT/FN 0.7025 instead of the
    # reference 0.6480). Both occurrences must be there (two lines), else the build stops.
    [[ $(grep -cE '^ *! *status *= *DftiSetValue\(dfti_back, *DFTI_OUTPUT_STRIDES, *strides_spac\)' "$s/m_aijpj.f90") -eq 2 ]] ||
      die "m_aijpj.f90: expected the two commented-out DFTI_OUTPUT_STRIDES lines of dfti_back (fft_makePrec, fft_VecAijPj)"
    port_edit "$s/m_aijpj.f90" '^ *! *status *= *DftiSetValue\(dfti_back, *DFTI_OUTPUT_STRIDES' \
      's/^( *)! *(status *= *DftiSetValue\(dfti_back, *DFTI_OUTPUT_STRIDES)/\1\2/'
    [[ $(grep -cE '^ *status *= *DftiSetValue\(dfti_back, *DFTI_OUTPUT_STRIDES, *strides_spac\)' "$s/m_aijpj.f90") -eq 2 ]] ||
      die "m_aijpj.f90: the output-stride edit did not give two active lines"
    mklinc="-DWITH_MKLFFT -I$mkl_inc"
    contact_libs="-Wl,--start-group $mkl_lib/libmkl_gf_lp64.a $mkl_lib/libmkl_sequential.a $mkl_lib/libmkl_core.a -Wl,--end-group -lpthread -lm -ldl"
  else
    # m_snorm: 'public test_fft' names a routine that exists only with WITH_MKLFFT.
    port_edit "$s/m_snorm.f90" '^public +test_fft *$' '/^public +test_fft *$/d'
    mklinc=
    contact_libs="-l:liblapack.a -l:libblas.a -lgfortran"
  fi
  mkdir -p "$s/obj/linux64_exe"
  [[ $(uname -m) == x86_64 ]] && arch=(-D__x86_64__) # VERSION's platform label; gfortran's cpp does not set it
  contact_fflags="-DTARGET_exe -I. $mklinc -cpp ${arch[*]} -O3 -ffree-line-length-none -fdec-format-defaults -Jobj/linux64_exe/"
  contact_fflags=$(echo "$contact_fflags" | tr -s ' ')
  (cd "$s" && nice make -j1 PROD=exe_l64 F90=gfortran OPENMP= MKLINC= MKLLIB="$contact_libs" \
    FFOPTS="$contact_fflags" >"$dst/build.log" 2>&1) || {
    tail -n 30 "$dst/build.log" >&2
    die "CONTACT did not build (log: $dst/build.log)"
  }
  [[ -x $dst/bin/contact_linux64 ]] || die "no CONTACT executable after the build"
  contact_build_line "$dst/bin/contact_linux64"
}

# contact_obtain_bin WORK: the CONTACT executable to run, into $contact_bin: $CONTACT_BIN when set (it must be
# executable), otherwise a build in WORK/contact-build (with MKL unless MKL=0). Either way $contact_build names it.
contact_obtain_bin() {
  local work=$1
  if [[ -n ${CONTACT_BIN:-} ]]; then
    contact_bin=$CONTACT_BIN
    [[ -x $contact_bin ]] || die "no CONTACT executable at $contact_bin"
    contact_build_line "$contact_bin"
  else
    if ((contact_mkl)); then
      contact_get_mkl
      say "building CONTACT with gfortran and Intel oneMKL $mkl_version (about a minute)"
    else
      say "building CONTACT with gfortran, without MKL (MKL=0; about a minute)"
    fi
    build_contact "$work/contact-build"
    contact_bin="$work/contact-build/bin/contact_linux64"
  fi
}

# contact_build: one line naming the build (for every table), from the flags of build_contact or, for a given
# executable, from what is linked into it (MKL's DFTI symbols, its version string).
contact_build_line() {
  local bin=$1 v
  if [[ -n ${contact_fflags:-} ]]; then
    if ((contact_mkl)); then
      contact_build="gfortran + Intel oneMKL $mkl_version (PyPI mkl-static/mkl-include; static, sequential: libmkl_gf_lp64 libmkl_sequential libmkl_core), WITH_MKLFFT, OPENMP=, FFOPTS='$contact_fflags', inverse-FFT output strides set (m_aijpj.f90)"
    else
      contact_build="gfortran, no MKL (WITH_MKLFFT undefined: no FFT products or preconditioners), OPENMP=, FFOPTS='$contact_fflags', MKLLIB='$contact_libs'"
    fi
  else
    # MKL's DFTI entry points (DFTI_COMMIT_DESCRIPTOR_EXTERNAL, ...) are linked statically into an MKL build.
    # (grep -c reads all of nm's output: grep -q would end the pipe early, which pipefail takes for a failure.)
    if [[ $(nm "$bin" 2>/dev/null | grep -ci 'dfti_commit_descriptor') -gt 0 ]]; then
      contact_build="given executable $bin: an MKL build (MKL's DFTI linked in)"
      contact_bin_mkl=1
    else
      contact_build="given executable $bin: no MKL (no DFTI symbols)"
      contact_bin_mkl=0
    fi
  fi
}

# --- Checking a build against CONTACT's reference outputs -----------------------------------------------------
#
# contact_ref_check NAME DIR REF: run the executable $contact_bin on DIR/NAME.inp (copied there by the caller) and
# compare the .out with the reference output REF (CONTACT's NAME.ref_out, the author's run with MKL on Windows).
# What is compared: every case's result blocks as CONTACT prints them at its output level (totals FN FX FY MZ,
# elastic energy, frictional work; FN/G, FX/FSTAT/FN, FY/FSTAT/FN, approach, PMAX; element counts NPOT NCON NADH
# NSLIP; the traction tables when printed), number by number, by contact_refcmp.py: each pair must agree to one
# unit of the last printed digit (the coarser of the two), plus a floor for the quantities that are noise around
# zero (see contact_refcmp.py). Any difference beyond that stops the caller (die): a build that does not reproduce
# the author's answers is not timed.
contact_ref_check() {
  local name=$1 dir=$2 ref=$3 report
  (cd "$dir" && "$contact_bin" 2 "$name" </dev/null >stdout.txt 2>&1) || die "CONTACT failed on $name (reference check)"
  [[ -f $dir/$name.out ]] || die "no $name.out after the reference check run"
  report=$(python3 "$contact_build_here/contact_refcmp.py" "$dir/$name.out" "$ref") || {
    echo "$report" >&2
    die "$name: this CONTACT build does not reproduce $name.ref_out (above); it is not timed"
  }
  say "  $name: $report"
  contact_ref_summary+=("$name: $report")
}
