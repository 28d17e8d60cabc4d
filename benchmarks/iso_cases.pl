% ISO Prolog conformance cases, written for robocram from the ISO/IEC 13211-1 rules.
% case(Id, Goal, Expected): Expected is true, false, or the Formal of error(Formal, _).
case(1, (X = f(X), Y = f(Y), X = Y), true).
case(2, unify_with_occurs_check(X, f(X)), false).
case(3, unify_with_occurs_check(f(X, Y), f(Y, a)), true).
case(4, (f(X, b) = f(a, Y), X == a, Y == b), true).
case(5, f(a) \= f(b), true).
case(6, functor(foo(a, b), foo, 2), true).
case(7, (functor(T, foo, 3), T = foo(_, _, _)), true).
case(8, functor(_, foo, -1), domain_error(not_less_than_zero, -1)).
case(9, functor(_, _, 3), instantiation_error).
case(10, functor(_, foo(a), 1), type_error(atomic, foo(a))).
case(11, (functor(T, 1.5, 0), T == 1.5), true).
case(12, arg(1, foo(a, b), a), true).
case(13, arg(3, foo(a, b), _), false).
case(14, arg(0, foo(a), _), false).
case(15, arg(a, foo(a), _), type_error(integer, a)).
case(16, arg(1, atom, _), type_error(compound, atom)).
case(17, arg(1, _, _), instantiation_error).
case(18, (foo(a, b) =.. L, L == [foo, a, b]), true).
case(19, (T =.. [foo, a], T == foo(a)), true).
case(20, _ =.. [foo|_], instantiation_error).
case(21, _ =.. [], domain_error(non_empty_list, [])).
case(22, _ =.. [f(a), b], type_error(atom, f(a))).
case(23, (copy_term(f(X, Y, X), C), C = f(A, B, A2), A == A2, A \== B), true).
case(24, atom_length(abc, 3), true).
case(25, atom_length(_, _), instantiation_error).
case(26, atom_length(abc, foo), type_error(integer, foo)).
case(27, atom_length(f(x), _), type_error(atom, f(x))).
case(28, (atom_concat(X, Y, ab), X == '', Y == ab), true).
case(29, (findall(X-Y, atom_concat(X, Y, abc), L), length(L, 4)), true).
case(30, atom_concat(_, b, _), instantiation_error).
case(31, (sub_atom(abcde, 1, 3, A, S), A == 1, S == bcd), true).
case(32, (findall(S, sub_atom(abc, _, 2, _, S), L), L == [ab, bc]), true).
case(33, sub_atom(_, _, _, _, _), instantiation_error).
case(34, (atom_chars(X, [a, b]), X == ab), true).
case(35, (atom_chars(abc, L), L == [a, b, c]), true).
case(36, atom_chars(_, [a|_]), instantiation_error).
case(37, atom_chars(_, [a, f(b)]), type_error(character, f(b))).
case(38, (atom_codes(X, [0'h, 0'i]), X == hi), true).
case(39, (char_code(C, 0'a), C == a), true).
case(40, char_code(ab, _), type_error(character, ab)).
case(41, char_code(_, _), instantiation_error).
case(42, (number_codes(X, [0'1, 0'2]), X == 12), true).
case(43, number_codes(_, [0'a]), syntax_error(_)).
case(44, (number_chars(X, [' ', '3']), X == 3), true).
case(45, number_chars(a, _), type_error(number, a)).
case(46, (number_chars(X, ['0', x, f]), X == 15), true).
case(47, (X is 7 // 2, X == 3), true).
case(48, (X is -7 // 2, X == -3), true).
case(49, (X is 7 mod -2, X == -1), true).
case(50, (X is -7 rem 2, X == -1), true).
case(51, _ is 1 / 0, evaluation_error(zero_divisor)).
case(52, _ is foo + 1, type_error(evaluable, foo/0)).
case(53, _ is _ + 1, instantiation_error).
case(54, (X is 2 ** 3, X =:= 8), true).
case(55, (X is max(1, 2.0), X == 2.0), true).
case(56, (X is abs(-3), X == 3), true).
case(57, (X is 5 / 2, X =:= 2.5), true).
case(58, 1 =:= 1.0, true).
case(59, 1 == 1.0, false).
case(60, (X is truncate(3.7), X == 3), true).
case(61, (X is 1 << 3, X == 8), true).
case(62, _ is 1 mod 0, evaluation_error(zero_divisor)).
case(63, 1.0 @< 1, true).
case(64, a @< f(a), true).
case(65, (compare(O, 1, a), O == (<)), true).
case(66, (msort([c, a, b, a], L), L == [a, a, b, c]), true).
case(67, (sort([c, a, b, a], L), L == [a, b, c]), true).
case(68, (keysort([b-1, a-2, b-0], L), L == [a-2, b-1, b-0]), true).
case(69, call((fail, 1)), type_error(callable, (fail, 1))).
case(70, call(_), instantiation_error).
case(71, call(1), type_error(callable, 1)).
case(72, (catch(throw(my), E, true), E == my), true).
case(73, catch(throw(a), b, true), a).
case(74, (findall(X, member(X, [a, b]), L), L == [a, b]), true).
case(75, (bagof(X, member(X, []), _)), false).
case(76, (bagof(X-Y, member(X-Y, [1-a, 2-b]), L), L == [1-a, 2-b]), true).
case(77, (findall(K-L, bagof(X, member(X-K, [1-a, 2-b, 3-a]), L), R), R == [a-[1, 3], b-[2]]), true).
case(78, (findall(L, bagof(X, Y^member(X-Y, [1-a, 2-b]), L), R), R == [[1, 2]]), true).
case(79, (setof(X, member(X, [c, b, a, b]), L), L == [a, b, c]), true).
case(80, (bagof(X, (X = A ; X = B), L), L == [A, B]), true).
case(81, findall(_, _, _), instantiation_error).
case(82, findall(_, 4, _), type_error(callable, 4)).
case(83, (assertz(cnt(0)), retract(cnt(0)), \+ cnt(_)), true).
case(84, assertz((foo :- 4)), type_error(callable, _)).
case(85, assertz(atom_length(a, 1)), permission_error(modify, static_procedure, atom_length/2)).
case(86, (asserta(d1(1)), asserta(d1(2)), findall(X, d1(X), L), L == [2, 1]), true).
case(87, (assertz(d2(1)), abolish(d2/1), catch(d2(_), error(existence_error(_, _), _), true)), true).
case(88, abolish(atom_length/2), permission_error(modify, static_procedure, atom_length/2)).
case(89, (assertz(d3(1)), retractall(d3(_)), \+ d3(_)), true).
case(90, (assertz(d4(a)), clause(d4(X), B), X == a, B == true), true).
case(91, clause(_, _), instantiation_error).
case(92, (assertz(d5(1)), current_predicate(d5/1)), true).
case(93, current_predicate(atom_length/2), false).
case(94, (current_prolog_flag(bounded, B), B == false), true).
case(95, set_prolog_flag(bounded, true), permission_error(modify, flag, bounded)).
case(96, set_prolog_flag(no_such_flag, 1), domain_error(prolog_flag, no_such_flag)).
case(99, (subsumes_term(f(_, b), f(a, b))), true).
case(100, subsumes_term(f(X, X), f(Y, Z)), false).
case(101, acyclic_term(f(_)), true).
case(102, (X = f(X), acyclic_term(X)), false).
case(103, (once(member(X, [a, b])), X == a), true).
case(104, (\+ fail), true).
case(105, ((true ; X = 1), var(X)), true).
case(106, ((fail -> true ; X = 2), X == 2), true).
case(107, (findall(X, (member(X, [1, 2, 3]), X > 1, !), L), L == [2]), true).
case(108, (length(L, 2), L = [_, _]), true).
case(109, length(_, -1), domain_error(not_less_than_zero, -1)).
case(110, length(a, _), type_error(list, a)).
case(111, (between(1, 3, X), X == 3), true).
case(112, (succ(X, 3), X == 2), true).
case(113, succ(_, 0), false).
case(114, (number_codes(N, [0'-, 0'1]), N == -1), true).
case(115, (atom_number('12', N), N == 12), true).
case(117, (catch(atom_length(1, _), error(E, _), true), (var(E) ; E = type_error(_, _))), true).
case(118, (upcase_atom(abc, X), X == 'ABC'), true).
case(119, (term_variables(f(X, g(Y, X)), L), L == [X, Y]), true).
case(120, (repeat, !), true).

case(121, (set_prolog_flag(occurs_check, true), (X = f(X) -> R = yes ; R = no),
           set_prolog_flag(occurs_check, false), R == no), true).
case(122, (set_prolog_flag(occurs_check, error), catch(X = f(X), error(E, _), true),
           set_prolog_flag(occurs_check, false), nonvar(E), E = occurs_check(_, _)), true).
case(123, (current_prolog_flag(occurs_check, F), F == false), true).
case(124, (set_prolog_flag(occurs_check, true), (iso_same(Y, g(Y)) -> R = yes ; R = no),
           set_prolog_flag(occurs_check, false), R == no), true).
case(125, (set_prolog_flag(occurs_check, false), asserta(iso_a(1)), asserta(iso_a(2)),
           findall(X, iso_a(X), L), retractall(iso_a(_)), L == [2, 1]), true).
case(126, (assertz(iso_b(1)), asserta(iso_b(0)), assertz(iso_b(2)), findall(X, iso_b(X), L),
           retractall(iso_b(_)), L == [0, 1, 2]), true).
case(127, (assertz(iso_c(1)), findall(X, (iso_c(X), Y is X + 1, asserta(iso_c(Y))), L),
           retractall(iso_c(_)), L == [1]), true).
case(128, (X = 1, (var(X) -> R = v ; integer(X) -> R = i ; R = o), R == i), true).
case(129, (atom_length(abc, N), N == 3), true).
case(130, atom_length(_, _), instantiation_error).
case(131, (sub_atom(abcde, 1, 3, A, S), S == bcd, A == 1), true).
case(132, atom_chars(_, [a|_]), instantiation_error).
case(133, (X is 7 // -2, X == -3), true).
case(134, (X is 7 mod -2, X == -1), true).
case(135, (X is -7 rem 2, X == -1), true).
case(136, _ is 1 / 0, evaluation_error(zero_divisor)).
case(137, _ is foo + 1, type_error(evaluable, foo/0)).
case(138, (X is max(1, 2.0), X == 2.0), true).
case(139, (X is truncate(-2.5), X == -2), true).
case(140, atom_codes(_, _), instantiation_error).
case(141, (copy_term(f(X, Y, X), C), C = f(A, B, D), A == D, A \== B), true).
case(142, (msort([b, a, c, a], L), L == [a, a, b, c]), true).
case(143, (keysort([b-1, a-2, b-0], L), L == [a-2, b-1, b-0]), true).
case(144, (setof(X, member(X, [c, a, b, a]), L), L == [a, b, c]), true).
case(145, bagof(X, member(X, []), _), false).
case(146, (catch(throw(my), B, true), B == my), true).
case(147, call(1), type_error(callable, 1)).
case(148, (char_code(C, 0'a), C == a), true).
case(149, char_code(_, _), instantiation_error).
case(150, (atom_chars(A, [a, b]), A == ab), true).
case(151, (number_chars(N, ['1', '2']), N == 12), true).
case(152, number_chars(_, [a]), syntax_error(_)).
case(153, (iso_kind(f(x), K), K == compound), true).
case(154, (iso_kind(_, K), K == var), true).
case(155, (findall(K, iso_kind(3, K), L), L == [small]), true).
case(156, abolish(foo/a), type_error(integer, a)).
case(157, abolish(1/2), type_error(atom, 1)).
case(158, abolish(foo/(-1)), domain_error(not_less_than_zero, -1)).
case(159, abolish(foo/_), instantiation_error).
case(160, (asserta((iso_v(X) :- X)), clause(iso_v(Y), B), B == call(Y)), true).
case(161, char_code(a, x), type_error(integer, x)).
case(162, current_predicate(0/dog), type_error(predicate_indicator, 0/dog)).
case(163, (set_prolog_flag(debug, off), current_prolog_flag(debug, F), F == false), true).
case(164, retract((atom(_) :- true)), permission_error(modify, static_procedure, atom/1)).
case(165, (findall(L, setof(X, member(X-_, [1-B, 2-_, 3-B]), L), R),
           R == [[1, 3], [2]]), true).
case(166, setof(X, X^(true ; 4), _), type_error(callable, (true ; 4))).
case(167, bagof(X, Y^(Y = 1 ; 4), _), type_error(callable, (_ = 1 ; 4))).

iso_same(X, X).
iso_kind(X, K) :- ( var(X) -> K = var ; integer(X), X < 10 -> K = small ; compound(X) -> K = compound
                  ; K = other ).

% The driver: one line per case, "Id pass|fail Result".
iso_result(G, R) :- catch((call(G) -> R = true ; R = false), Ball, iso_ball(Ball, R)).
iso_ball(error(F, _), F) :- !.
iso_ball(B, B).
iso_run :-
    forall(case(I, G, E),
           ( iso_result(G, R),
             ( subsumes_term(E, R) -> S = pass ; S = fail ),
             format("~w ~w ~q~n", [I, S, R]) )).
