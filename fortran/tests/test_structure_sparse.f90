! SPDX-License-Identifier: GPL-3.0-or-later
! test_structure_sparse.f90 — the structure's compressed sparse setters through type
! fricreg_structure: set_mass_csc, set_stiffness_csc, set_damping_csc, set_contacts_csc and
! their _csr twins, and set_matrix, the one setter of which they and the dense ones are cases.
!
! A chain of three degrees of freedom with two contacts (ground slip of dof 1, slip between
! dofs 2 and 3): a consistent (tridiagonal) M, K and a damping matrix C, J(2, 3) in Fortran's
! order, a constant load and an initial velocity that make both contacts move. It is set up
! three times and stepped 25 times by average-acceleration Newmark:
!   - by the dense setters (the reference);
!   - by one-based compressed columns, M, K and C by their lower triangle, J whole (the arrays
!     a Fortran code holds), the flags given and, for J, absent (one-based);
!   - by compressed rows: M zero-based and whole, K one-based by its upper triangle, C with
!     the flags absent (one-based, whole), J zero-based;
!   - by set_matrix's dense form (values(:, :), J in Fortran's order);
!   - by set_matrix's compressed form, CSC and CSR mixed, flags given and absent.
! Every displacement, velocity, acceleration and force equals the dense path's bit for bit:
! the three make the same CHOLMOD matrices (a symmetric matrix's symmetric part is itself).
! Then the refusals: array sizes checked in Fortran (FRICREG_ESIZE naming the array), C's
! refusals of a bad column pointer, a wrong base, a triangle flag for J and a zero row of J
! (FRICREG_EINVAL with C's message), an object not created (FRICREG_ENULL), set_matrix's
! which = 0, a dense format in its compressed form and a J of the wrong shape; the model after
! them is still the one set before (the run equals the dense one again).
program test_structure_sparse
  use fricreg
  use ftest
  implicit none
  integer, parameter :: ndof = 3, ncontacts = 2, nsteps = 25
  real(c_double), parameter :: dt = 0.0137_c_double, eps = 0.0213_c_double
  real(c_double), parameter :: mun(ncontacts) = [0.437_c_double, 0.291_c_double]
  real(c_double), parameter :: p(ndof) = [0.61_c_double, -0.42_c_double, 0.93_c_double]
  real(c_double), parameter :: v0(ndof) = [0.5_c_double, -0.3_c_double, 0.8_c_double]
  real(c_double) :: M(ndof, ndof), K(ndof, ndof), C(ndof, ndof), J(ncontacts, ndof)
  real(c_double) :: ref(3 * ndof + ncontacts), got(3 * ndof + ncontacts)
  type(fricreg_structure) :: st, empty
  integer(c_int64_t), allocatable :: ptr(:), ind(:)
  real(c_double), allocatable :: val(:)
  integer(c_int64_t) :: bad(ndof + 1)
  integer :: i

  ! Stored as Fortran arrays (column by column); M, K, C symmetric.
  M = reshape([2.31_c_double, 0.17_c_double, 0.0_c_double, &
               0.17_c_double, 1.43_c_double, -0.08_c_double, &
               0.0_c_double, -0.08_c_double, 0.87_c_double], [ndof, ndof])
  K = reshape([41.3_c_double, -17.9_c_double, 0.0_c_double, &
               -17.9_c_double, 29.6_c_double, -11.7_c_double, &
               0.0_c_double, -11.7_c_double, 11.7_c_double], [ndof, ndof])
  C = reshape([0.21_c_double, -0.05_c_double, 0.0_c_double, &
               -0.05_c_double, 0.13_c_double, -0.02_c_double, &
               0.0_c_double, -0.02_c_double, 0.04_c_double], [ndof, ndof])
  J = 0.0_c_double
  J(1, 1) = 1.0_c_double  ! contact 1: dof 1 on the ground
  J(2, 2) = -1.0_c_double ! contact 2: dof 3 relative to dof 2
  J(2, 3) = 1.0_c_double

  ! ---- The reference: the dense setters ----------------------------------------------------
  call check_status(st%create(ndof, ncontacts), FRICREG_OK, 'dense: create')
  call check_status(st%set_mass(M), FRICREG_OK, 'dense: set_mass')
  call check_status(st%set_stiffness(K), FRICREG_OK, 'dense: set_stiffness')
  call check_status(st%set_damping(C), FRICREG_OK, 'dense: set_damping')
  call check_status(st%set_contacts(J), FRICREG_OK, 'dense: set_contacts')
  call run(st, 'dense', ref)
  call check(all(ref(1:ndof) /= 0.0_c_double), 'dense: every dof has moved')
  call check(all(abs(ref(3 * ndof + 1:)) > 0.0_c_double), 'dense: both contacts carry a force')
  call st%destroy()

  ! ---- One-based compressed columns, the lower triangles (as Fortran codes hold them) -------
  call check_status(st%create(ndof, ncontacts), FRICREG_OK, 'csc: create')
  call compress(M, .true., 1, -1, ptr, ind, val)
  call check_status(st%set_mass_csc(ptr, ind, val, &
                                    FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_OK, 'set_mass_csc, one-based lower triangle')
  call compress(K, .true., 1, -1, ptr, ind, val)
  call check_status(st%set_stiffness_csc(ptr, ind, val, &
                                         FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_OK, 'set_stiffness_csc, one-based lower triangle')
  call compress(C, .true., 1, -1, ptr, ind, val)
  call check_status(st%set_damping_csc(ptr, ind, val, &
                                       FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_OK, 'set_damping_csc, one-based lower triangle')
  call compress(J, .true., 1, 0, ptr, ind, val)
  call check_status(st%set_contacts_csc(ptr, ind, val), FRICREG_OK, &
                    'set_contacts_csc, flags absent (one-based)')
  call run(st, 'csc', got)
  do i = 1, size(ref)
    call check_bits(got(i), ref(i), 'csc: number ' // str(i) // ' as the dense setters''')
  end do
  call st%destroy()

  ! ---- Compressed rows, zero- and one-based, whole and by the upper triangle ---------------
  call check_status(st%create(ndof, ncontacts), FRICREG_OK, 'csr: create')
  call compress(M, .false., 0, 0, ptr, ind, val)
  call check_status(st%set_mass_csr(ptr, ind, val, FRICREG_SPARSE_ZERO_BASED), FRICREG_OK, &
                    'set_mass_csr, zero-based whole')
  call compress(K, .false., 1, 1, ptr, ind, val)
  call check_status(st%set_stiffness_csr(ptr, ind, val, &
                                         FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER), &
                    FRICREG_OK, 'set_stiffness_csr, one-based upper triangle')
  call compress(C, .false., 1, 0, ptr, ind, val)
  call check_status(st%set_damping_csr(ptr, ind, val), FRICREG_OK, &
                    'set_damping_csr, flags absent (one-based whole)')
  call compress(J, .false., 0, 0, ptr, ind, val)
  call check_status(st%set_contacts_csr(ptr, ind, val, FRICREG_SPARSE_ZERO_BASED), FRICREG_OK, &
                    'set_contacts_csr, zero-based')
  call run(st, 'csr', got)
  do i = 1, size(ref)
    call check_bits(got(i), ref(i), 'csr: number ' // str(i) // ' as the dense setters''')
  end do
  call st%destroy()

  ! ---- set_matrix, dense: values in Fortran's order, J (m, ndof) as set_contacts ------------
  call check_status(st%create(ndof, ncontacts), FRICREG_OK, 'set_matrix dense: create')
  call check_status(st%set_matrix(FRICREG_MASS, M), FRICREG_OK, 'set_matrix(FRICREG_MASS, M)')
  call check_status(st%set_matrix(FRICREG_STIFFNESS, K), FRICREG_OK, &
                    'set_matrix(FRICREG_STIFFNESS, K)')
  call check_status(st%set_matrix(FRICREG_DAMPING, C), FRICREG_OK, &
                    'set_matrix(FRICREG_DAMPING, C)')
  call check_status(st%set_matrix(FRICREG_CONTACTS, J), FRICREG_OK, &
                    'set_matrix(FRICREG_CONTACTS, J)')
  call run(st, 'set_matrix dense', got)
  do i = 1, size(ref)
    call check_bits(got(i), ref(i), 'set_matrix dense: number ' // str(i) // &
                    ' as the dense setters''')
  end do
  call st%destroy()

  ! ---- set_matrix, compressed: CSC and CSR, flags given and absent -------------------------
  call check_status(st%create(ndof, ncontacts), FRICREG_OK, 'set_matrix compressed: create')
  call compress(M, .true., 1, -1, ptr, ind, val)
  call check_status(st%set_matrix(FRICREG_MASS, FRICREG_MATRIX_CSC, ptr, ind, val, &
                                  FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_OK, 'set_matrix(FRICREG_MASS, CSC), one-based lower triangle')
  call compress(K, .false., 0, 1, ptr, ind, val)
  call check_status(st%set_matrix(FRICREG_STIFFNESS, FRICREG_MATRIX_CSR, ptr, ind, val, &
                                  FRICREG_SPARSE_ZERO_BASED + FRICREG_SPARSE_UPPER), &
                    FRICREG_OK, 'set_matrix(FRICREG_STIFFNESS, CSR), zero-based upper triangle')
  call compress(C, .true., 1, 0, ptr, ind, val)
  call check_status(st%set_matrix(FRICREG_DAMPING, FRICREG_MATRIX_CSC, ptr, ind, val), &
                    FRICREG_OK, 'set_matrix(FRICREG_DAMPING, CSC), flags absent (one-based)')
  call compress(J, .false., 1, 0, ptr, ind, val)
  call check_status(st%set_matrix(FRICREG_CONTACTS, FRICREG_MATRIX_CSR, ptr, ind, val), &
                    FRICREG_OK, 'set_matrix(FRICREG_CONTACTS, CSR), rowptr(m + 1)')
  call run(st, 'set_matrix compressed', got)
  do i = 1, size(ref)
    call check_bits(got(i), ref(i), 'set_matrix compressed: number ' // str(i) // &
                    ' as the dense setters''')
  end do
  call st%destroy()

  ! ---- Refusals: each recorded with its message, the model kept ----------------------------
  call check_status(st%create(ndof, ncontacts), FRICREG_OK, 'refusals: create')
  call check_status(st%set_mass(M), FRICREG_OK, 'refusals: set_mass')
  call check_status(st%set_stiffness(K), FRICREG_OK, 'refusals: set_stiffness')
  call check_status(st%set_damping(C), FRICREG_OK, 'refusals: set_damping')
  call check_status(st%set_contacts(J), FRICREG_OK, 'refusals: set_contacts')
  ! A column pointer that decreases (one-based lower triangle of a diagonal I: colptr = 1 2 3 4).
  bad = [1_c_int64_t, 3_c_int64_t, 2_c_int64_t, 4_c_int64_t]
  call check_status(st%set_mass_csc(bad, [1_c_int64_t, 2_c_int64_t, 3_c_int64_t], &
                                    [1.0_c_double, 1.0_c_double, 1.0_c_double], &
                                    FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_EINVAL, 'set_mass_csc: colptr decreasing')
  call check_status(st%errcode(), FRICREG_EINVAL, 'errcode after colptr decreasing')
  call check(index(st%errmsg(), 'set_mass_csc: colptr') == 1, 'message: ' // st%errmsg())
  ! Zero-based arrays with the flags absent (one-based): colptr(1) = 0 is not the base.
  call compress(K, .true., 0, -1, ptr, ind, val)
  call check_status(st%set_stiffness_csc(ptr, ind, val), FRICREG_EINVAL, &
                    'set_stiffness_csc: zero-based arrays read as one-based')
  call check(index(st%errmsg(), 'set_stiffness_csc: colptr') == 1, 'message: ' // st%errmsg())
  ! Sizes, checked in Fortran before C reads anything.
  call compress(C, .true., 1, -1, ptr, ind, val)
  call check_status(st%set_damping_csc(ptr(1:ndof), ind, val, &
                                       FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_ESIZE, 'set_damping_csc: colptr of ndof elements')
  call check(st%errmsg() == 'set_damping_csc: size(colptr) = 3, expected 4', &
             'message: ' // st%errmsg())
  call check_status(st%set_damping_csc(ptr, ind(1:size(ind) - 1), val, &
                                       FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_ESIZE, 'set_damping_csc: rowind shorter than nnz')
  call check(index(st%errmsg(), 'set_damping_csc: size(rowind) = ') == 1, &
             'message: ' // st%errmsg())
  call check_status(st%set_damping_csr(ptr, ind, val(1:1), &
                                       FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER), &
                    FRICREG_ESIZE, 'set_damping_csr: values shorter than nnz')
  call check(index(st%errmsg(), 'set_damping_csr: size(values) = 1, expected at least') == 1, &
             'message: ' // st%errmsg())
  call compress(J, .false., 1, 0, ptr, ind, val)
  call check_status(st%set_contacts_csc(ptr, ind, val), FRICREG_ESIZE, &
                    'set_contacts_csc given the row pointers (m + 1, not ndof + 1)')
  call check(st%errmsg() == 'set_contacts_csc: size(colptr) = 3, expected 4', &
             'message: ' // st%errmsg())
  ! J is not symmetric: a triangle flag is refused by C.
  call check_status(st%set_contacts_csr(ptr, ind, val, &
                                        FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER), &
                    FRICREG_EINVAL, 'set_contacts_csr with a triangle flag')
  call check(index(st%errmsg(), 'set_contacts_csr: ') == 1, 'message: ' // st%errmsg())
  ! A contact that does not move: row 2 of J emptied (rowptr = 1 2 2).
  call check_status(st%set_contacts_csr([1_c_int64_t, 2_c_int64_t, 2_c_int64_t], &
                                        [1_c_int64_t], [1.0_c_double]), &
                    FRICREG_EINVAL, 'set_contacts_csr: a zero row')
  call check(index(st%errmsg(), 'set_contacts_csr: row 1 of J is zero') == 1, &
             'message (C counts from 0): ' // st%errmsg())
  ! set_matrix: which not a model matrix (C's refusal, before it reads anything), both forms.
  call check_status(st%set_matrix(0_c_int, M), FRICREG_EINVAL, 'set_matrix(which = 0, M)')
  call check(index(st%errmsg(), 'set_matrix: which = 0 is not a model matrix') == 1, &
             'message: ' // st%errmsg())
  call check_status(st%set_matrix(0_c_int, FRICREG_MATRIX_CSR, ptr, ind, val), FRICREG_EINVAL, &
                    'set_matrix(which = 0, CSR)')
  call check(index(st%errmsg(), 'set_matrix: which = 0 is not a model matrix') == 1, &
             'message: ' // st%errmsg())
  ! A dense format in the compressed form (refused here: values(:) is no dense matrix).
  call check_status(st%set_matrix(FRICREG_CONTACTS, FRICREG_MATRIX_DENSE, ptr, ind, val, &
                                  FRICREG_SPARSE_ZERO_BASED), FRICREG_EINVAL, &
                    'set_matrix(FRICREG_MATRIX_DENSE, ptr, ind, values(:))')
  call check(index(st%errmsg(), 'set_matrix: format = 0 is neither') == 1, &
             'message: ' // st%errmsg())
  ! J given as ndof x ndof, and CSR J's rowptr of ndof + 1 elements.
  call check_status(st%set_matrix(FRICREG_CONTACTS, M), FRICREG_ESIZE, &
                    'set_matrix(FRICREG_CONTACTS, ndof x ndof)')
  call check(st%errmsg() == 'set_matrix: size(values, 1) = 3, expected 2', &
             'message: ' // st%errmsg())
  call compress(J, .true., 1, 0, ptr, ind, val)
  call check_status(st%set_matrix(FRICREG_CONTACTS, FRICREG_MATRIX_CSR, ptr, ind, val), &
                    FRICREG_ESIZE, 'set_matrix(FRICREG_CONTACTS, CSR) given the column pointers')
  call check(st%errmsg() == 'set_matrix: size(ptr) = 4, expected 3', 'message: ' // st%errmsg())
  ! J is not symmetric: a triangle flag is refused by C.
  call check_status(st%set_matrix(FRICREG_CONTACTS, FRICREG_MATRIX_CSC, ptr, ind, val, &
                                  FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_EINVAL, 'set_matrix(FRICREG_CONTACTS, CSC) with a triangle flag')
  call check(index(st%errmsg(), 'set_matrix: ') == 1, 'message: ' // st%errmsg())
  call check_status(empty%set_matrix(FRICREG_MASS, M), FRICREG_ENULL, 'set_matrix, not created')
  ! Not created.
  call check_status(empty%set_mass_csc(ptr, ind, val), FRICREG_ENULL, 'set_mass_csc, not created')
  call check(empty%errmsg() == 'set_mass_csc: the structure is not created (call create)', &
             'message: ' // empty%errmsg())
  ! The refusals changed nothing: the dense run again, bit for bit.
  call run(st, 'after the refusals', got)
  do i = 1, size(ref)
    call check_bits(got(i), ref(i), 'after the refusals: number ' // str(i))
  end do
  call st%destroy()
  deallocate (ptr, ind, val) ! a main program's allocatables live on: LeakSanitizer counts them
  call finish('test_structure_sparse')

contains

  !> The settings beside the model, nsteps Newmark steps, and the state and forces after them:
  !> out = (u, v, a, f).
  subroutine run(s, what, out)
    type(fricreg_structure), intent(inout) :: s
    character(len=*), intent(in) :: what
    real(c_double), intent(out) :: out(:)
    integer :: n
    out = 0.0_c_double
    call check_status(s%set_bounds(mun), FRICREG_OK, what // ': set_bounds')
    call check_status(s%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, what // ': set_law')
    call check_status(s%set_load(p), FRICREG_OK, what // ': set_load')
    call check_status(s%set_initial(v0=v0), FRICREG_OK, what // ': set_initial')
    do n = 1, nsteps
      call check_status(s%step(dt), FRICREG_OK, what // ': step ' // str(n))
    end do
    call check_status(s%get_state(out(1:ndof), out(ndof + 1:2 * ndof), &
                                  out(2 * ndof + 1:3 * ndof)), FRICREG_OK, what // ': get_state')
    call check_status(s%get_forces(out(3 * ndof + 1:)), FRICREG_OK, what // ': get_forces')
  end subroutine run

  !> The nonzero entries of A in compressed columns (by_columns) or rows, indices from base
  !> (0 or 1), whole (triangle 0), or its upper (1: row <= column) or lower (-1: row >= column)
  !> triangle with the diagonal.
  subroutine compress(A, by_columns, base, triangle, ptr, ind, val)
    real(c_double), intent(in) :: A(:, :)
    logical, intent(in) :: by_columns
    integer, intent(in) :: base, triangle
    integer(c_int64_t), allocatable, intent(out) :: ptr(:), ind(:)
    real(c_double), allocatable, intent(out) :: val(:)
    integer :: outer, inner, row, col, nnz, nouter, ninner
    nouter = merge(size(A, 2), size(A, 1), by_columns)
    ninner = merge(size(A, 1), size(A, 2), by_columns)
    allocate (ptr(nouter + 1), ind(size(A)), val(size(A)))
    nnz = 0
    ptr(1) = base
    do outer = 1, nouter
      do inner = 1, ninner
        row = merge(inner, outer, by_columns)
        col = merge(outer, inner, by_columns)
        if (A(row, col) == 0.0_c_double) cycle
        if (triangle > 0 .and. row > col) cycle
        if (triangle < 0 .and. row < col) cycle
        nnz = nnz + 1
        ind(nnz) = inner - 1 + base
        val(nnz) = A(row, col)
      end do
      ptr(outer + 1) = nnz + base
    end do
    ind = ind(1:nnz)
    val = val(1:nnz)
  end subroutine compress

  function str(n) result(s)
    integer, intent(in) :: n
    character(len=:), allocatable :: s
    character(len=12) :: buf
    write (buf, '(i0)') n
    s = trim(buf)
  end function str

end program test_structure_sparse
